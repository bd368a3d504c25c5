# c11-B12: the Lennard-Jones potential U = U0((a/r)^12 - (b/r)^6) with a = b = 1. Expected
# equilibrium r = 2^(1/6) a^2/b = 1.122462. Exercises: mechkit potential (F = -dU/dr
# symbolically, its roots on the range, stability from U'').
mechkit potential "U0*((a/r)^12-(b/r)^6)" --var r --range 0.8:3 --set U0=1,a=1,b=1 --energy=-0.1 -o out/book/c11-B12-lennard-jones --json
#> answer = /equilibria/0/x
