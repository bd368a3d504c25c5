# c08-B9: the tip of a helicopter rotor blade (R = 5 m) turning at 200 rpm (inputs inferred from
# the book's answers). Expected: tip speed v ≈ 104.7 m/s and centripetal acceleration
# a ≈ 2193 m/s² (2.2 km/s², towards the hub). Exercises: mechkit rotation, uniform circular
# motion from an angular speed in rpm (v = ωR, a = ω²R).
mechkit rotation --angular-speed "200 rpm" --radius "5 m" --json
#> v = /speed
#> a = /centripetal
