# c14-B11: a point on the surface of the rotating Earth (R = 6378 km, one turn in 86400 s): ω,
# the speed and centripetal acceleration at the equator, and the centripetal acceleration at
# latitude 60° (Oslo), where the circle's radius is R cos 60°. Expected ω = 7.27e-5 rad/s,
# v = 463.8 m/s, a = 0.034 m/s² at the equator, 0.017 m/s² at 60°. Exercises: mechkit rotation
# --period --radius --latitude.
mechkit rotation --period "86400 s" --radius "6378 km" --latitude "60 deg" --json
#> omega = /omega
#> v_eq = /speed
#> a_eq = /centripetal
#> a_lat = /latitude/centripetal
