# c14-B6: Earth's angular speed in its orbit (one turn in 365.25 days) and about its axis (one
# turn in a 24 h day, 86400 s). Expected ω_orbit = 1.99e-7 rad/s, ω_spin = 7.27e-5 rad/s.
# Exercises: mechkit rotation --period (ω = 2π/T, with the day unit d).
mechkit rotation --period "365.25 d" --json
#> omega_orbit = /omega
mechkit rotation --period "86400 s" --json
#> omega_spin = /omega
