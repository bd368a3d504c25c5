# c14-B10: a runner at a constant 10 m/s on a circular curve of radius 50 m; the angular velocity,
# the angular acceleration and the (centripetal) acceleration. Expected ω = 0.2 rad/s, α = 0,
# a = v²/R = 2 m/s². Exercises: mechkit rotation --speed --radius (circular motion).
mechkit rotation --speed "10 m/s" --radius "50 m" --json
#> omega = /omega
#> alpha = /alpha
#> a = /centripetal
