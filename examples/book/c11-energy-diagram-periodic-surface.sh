# c11: an atom on a surface feels F = -F0 sin(2 pi x/b) (F0 = b = 1). Expected: stable
# equilibria at x = n b, unstable at (n + 1/2) b, barrier U(max) - U(min) = F0 b/pi = 0.31831.
# Exercises: mechkit potential --force (U = -∫F dx symbolically, equilibria and their
# stability, barriers); every equilibrium found over three periods must be of its pattern.
mechkit potential --force "-F0*sin(2*pi*x/b)" --range=-1.25:1.75 --set F0=1,b=1 --energy=-0.1 -o out/book/c11-periodic-surface --json
#> barrier_dU = /equilibria/0/barrier
#> stable = /by_stability/stable
#> unstable = /by_stability/unstable
