# c05-B27: an aluminium wire treated as a spring; a hanging load m = 10 kg stretches it by
# dx = 1 mm (inputs inferred from the book's answer, g = 9.8 m/s²). Expected k = m g/dx =
# 98 kN/m. Exercises: mechkit solve (the equilibrium k dx = m g solved for k symbolically and
# evaluated with units).
mechkit solve "k*dx = m*g" --for k --set "dx=1 mm,m=10 kg,g=9.8 m/s^2" --json
#> answer = /numeric/0
