# c08-B10: a train at 200 km/h turns through 90° on the smallest circle its passengers allow,
# a centripetal acceleration of at most 0.1 g (g = 9.81 m/s²; speed and limit inferred).
# Expected: R = v²/a = 3146.2 m and t = πR/(2v) = 88.96 s. Exercises: mechkit rotation with
# --centripetal (the radius from the acceleration limit) and --turn (the time for an angle).
mechkit rotation --speed "200 km/h" --centripetal "0.981 m/s^2" --turn "90 deg" --json
#> R = /radius
#> t = /turn/time
