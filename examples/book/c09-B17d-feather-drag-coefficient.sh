# c09-B17d: a feather falls h = 2.4 m in 4.8 s, at its terminal speed all the way. Expected:
# v_T = 0.5 m/s and D/(m g) = 1/v_T^2 = 4 s^2/m^2 for quadratic drag D v^2.
# Exercises: mechkit terminal, drag from a measured terminal velocity (the weight balances the
# drag: m g = D v_T^2).
mechkit terminal --distance "2.4 m" --time "4.8 s" --law quadratic --json
#> answer = /per_weight
