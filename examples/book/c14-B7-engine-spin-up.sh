# c14-B7: an engine speeds up uniformly from 1000 rpm to 2000 rpm in 15 s; its angular
# acceleration and the revolutions it makes meanwhile. Expected α = 6.98 rad/s², 375 rev.
# Exercises: mechkit rotation --omega0 --omega1 --time (uniform angular acceleration, rpm units).
mechkit rotation --omega0 "1000 rpm" --omega1 "2000 rpm" --time "15 s" --json
#> alpha = /alpha
#> revolutions = /revolutions
