# c11-B8: a cart released from height h runs through a vertical loop of radius R = 1 m; at the
# top it needs v_top^2 >= g R. Expected minimum h = 5R/2 = 2.5 m. Exercises: mechkit solve
# (energy conservation m g h = m g 2R + m v_top^2/2 with v_top^2 = g R, solved for h).
mechkit solve "m*g*h = m*g*2*R + m*(g*R)/2" --for h --set "m=1 kg,g=9.81 m/s^2,R=1 m" --json
#> answer = /numeric/0
