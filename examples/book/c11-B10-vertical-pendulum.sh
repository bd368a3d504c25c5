# c11-B10: a ball on a 1 m string gets speed v0 at the bottom; the string stays taut over the
# top if v_top^2 >= g L. Expected minimum v0 = sqrt(5 g L) = 7.0036 m/s. Exercises: mechkit
# solve (energy conservation v0^2/2 = 2 g L + v_top^2/2, the positive root).
mechkit solve "v0^2/2 = 2*g*L + g*L/2" --for v0 --set "g=9.81 m/s^2,L=1 m" --json
#> answer = /numeric/1
