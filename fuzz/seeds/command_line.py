#!/usr/bin/env python3
# Run from the repository root: python3 fuzz/seeds/command_line.py .
# Builds fuzz/seeds/command_line/ from the command lines of docs/, README.md and the gallery's
# scripts (examples/book/*.sh): byte 0 the subcommand, the arguments one per line, and the
# file an argument names (under examples/) after a NUL, named in.EXT in the argument.
import glob, hashlib, os, re, shlex, sys
repo = sys.argv[1]
subs = ["run","check","animate","list-integrators","diff","integrate","solve","units","potential","power","rocket","derive","spin","md","collide","impulse","com","inertia","rotation","relative","terminal","bead","rigid-collide","work","friction","roll","sweep","sweep-merge","gallery","completions","man"]
lines = []
for path in [os.path.join(repo, "README.md")] + glob.glob(os.path.join(repo, "docs/*.md")) + glob.glob(os.path.join(repo, "examples/book/*.sh")) + [os.path.join(repo, "crates/mechkit-cli/src/args/cli.rs")]:
    for l in open(path, encoding="utf-8"):
        m = re.match(r'^\s*(?:\$ )?mechkit ([a-z-]+)(.*)$', l.rstrip("\n"))
        if m and m.group(1) in subs and "[" not in m.group(2) and "<" not in m.group(2) and "|" not in m.group(2):
            lines.append((m.group(1), m.group(2)))
out = os.path.join(repo, "fuzz/seeds/command_line")
n = 0
seen = set()
for sub, rest in lines:
    rest = rest.split(" #")[0].replace("\\", "")
    try:
        args = shlex.split(rest)
    except ValueError:
        continue
    file = None
    ok = True
    for i, a in enumerate(args):
        for pre in ("examples/", "../"):
            pass
        cand = os.path.join(repo, a)
        if "/" in a and os.path.isfile(cand) and file is None:
            ext = os.path.splitext(a)[1].lower()
            name = {".toml": "in.toml", ".png": "in.png", ".jpg": "in.png"}.get(ext, "in.csv")
            file = open(cand, "rb").read()
            if len(file) > 8000:
                ok = False
            args[i] = name
        elif a.startswith("/") or ".." in a:
            ok = False
        elif "/" in a and a.startswith(("out", "results", "report")):
            args[i] = a.split("/")[-1]
    if not ok:
        continue
    data = bytes([subs.index(sub)]) + "\n".join(args).encode()
    if file is not None:
        data += b"\0" + file
    h = hashlib.sha1(data).hexdigest()[:16]
    if h in seen:
        continue
    seen.add(h)
    open(os.path.join(out, sub + "-" + h), "wb").write(data)
    n += 1
print(n, "seeds")
