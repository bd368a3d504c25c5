# c10-B13: a hydro station where 100 kg of water per second falls 10 m. Expected P = (dm/dt) g h
# = 9800 W. Exercises: mechkit solve (the power equation solved for P).
mechkit solve "P = mdot*g*h" --for P --set "mdot=100 kg/s,g=9.8 m/s^2,h=10 m" --json
#> answer = /numeric/0
