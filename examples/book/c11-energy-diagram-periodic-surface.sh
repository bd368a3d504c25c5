# c11: an atom on a surface feels F = -F0 sin(2 pi x/b) (F0 = b = 1). Expected: stable
# equilibria at x = n b, unstable at (n + 1/2) b, barrier U(max) - U(min) = F0 b/pi = 0.31831.
# Exercises: mechkit potential --force (U = -∫F dx symbolically, equilibria, barriers).
mechkit potential --force "-F0*sin(2*pi*x/b)" --range=-0.25:0.75 --set F0=1,b=1 --energy=-0.1 --plot out/book/c11-periodic-surface.svg --json
#> barrier_dU = /equilibria/0/barrier
