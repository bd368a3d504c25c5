# c06-B19: a plane flying at 300 km/h through the air must travel due north while a 60 km/h
# wind blows across its track (towards the east). Expected: it heads 78.5 degrees from the
# upwind direction (11.5 degrees into the wind) and covers the ground at 293.9 km/h.
# Exercises: mechkit relative, the Galilean transformation v_ground = v_air + v_wind solved for
# the heading that keeps the ground velocity on the track.
mechkit relative --speed "300 km/h" --current "60 km/h" --current-direction east --track north --in "km/h" --json
#> v_ground_kmh = /ground_speed
#> heading_deg = /angle_to_upstream_deg
