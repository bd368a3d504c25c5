# c10: integrate F(x) = 1/(a + x^2) symbolically (MATLAB syms/int), and from 0 to 1 with a = 1
# by the closed form and by the trapezoidal rule with 10 intervals. Expected antiderivative
# atan(x/sqrt(a))/sqrt(a), definite 0.785398, trapezoid 0.784981. Exercises: mechkit integrate
# (rule table, verified by differentiation; fixed rules next to the exact value).
mechkit integrate "1/(a+x^2)" --var x --from 0 --to 1 --set a=1 --method trapezoid --n 10 --json
#> antiderivative = /antiderivative
#> definite = /definite/closed_form
#> trapz_n10 = /rules/0/value
