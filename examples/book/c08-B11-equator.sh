# c08-B11: a point on the equator (R = 6378 km) turning once in 24 h. Expected: v = 463.8 m/s
# and a = 0.0337 m/s² (0.0034 g). Exercises: mechkit rotation, circular motion from a period.
mechkit rotation --period "86400 s" --radius "6378 km" --json
#> v = /speed
#> a = /centripetal
