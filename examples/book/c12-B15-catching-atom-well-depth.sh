# c12-B15: a radial spring force F = -k(r - b) acts for b - d < r < b + d (k = 100, b = 1,
# d = 0.5). Expected well depth U0 = k d^2/2 = 12.5: the work needed to pull the atom from the
# bottom r = b to the edge r = b + d. Exercises: mechkit integrate (closed form and quadrature).
mechkit integrate "k*(r - b)" --var r --from b --to b+d --set k=100,b=1,d=0.5 --json
#> answer = /definite/closed_form
