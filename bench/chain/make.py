"""Writes a scenario file of a 1-D chain of COUNT stiff damped springs (k = 1e6 N/m,
dashpots of 2e4 N*s/m as pair formula forces, the first mass tied to a wall, the last pulled
by 1 kN) for METHOD at RTOL to T_MAX: the many-body case of docs/benchmarks.md.

    python3 bench/chain/make.py METHOD RTOL COUNT T_MAX > chain.toml
"""
import sys


def chain(method: str, rtol: float, count: int, t_max: str) -> str:
    s = (
        'dimensions = 1\n[constants]\nk = "1e6 N/m"\nc = "2e4 N*s/m"\nF0 = "1000 N"\n'
        f'[integrator]\nmethod = "{method}"\nrtol = {rtol}\natol = {rtol * 1e-3}\n'
        f'[stop]\nt_max = "{t_max}"\n[observe]\n'
        f'x_end = "final(m{count - 1}.x)"\nx_mid = "final(m{count // 2 - 1}.x)"\n'
    )
    for i in range(count):
        s += f'[[body]]\nname = "m{i}"\nmass = "1 kg"\nposition = "{i + 1} m"\nvelocity = "0 m/s"\n'
    s += '[[force]]\nname = "wall"\nkind = "expression"\non = "m0"\nF = "-k*(x - 1) - c*v"\n'
    for i in range(1, count):
        s += (
            f'[[force]]\nname = "s{i}"\nkind = "spring"\nk = "k"\nrest_length = "1 m"\n'
            f'between = ["m{i - 1}", "m{i}"]\n'
            f'[[force]]\nname = "d{i}"\nkind = "expression"\non = "m{i}"\nF = "-c*(v - m{i - 1}.v)"\n'
            f'[[force]]\nname = "e{i}"\nkind = "expression"\non = "m{i - 1}"\nF = "-c*(v - m{i}.v)"\n'
        )
    s += f'[[force]]\nname = "pull"\nkind = "expression"\non = "m{count - 1}"\nF = "F0"\n'
    return s


if __name__ == "__main__":
    method, rtol, count, t_max = sys.argv[1], float(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
    sys.stdout.write(chain(method, rtol, count, t_max))
