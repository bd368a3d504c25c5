# c12-B6: a 1000 kg car at 10 m/s stopped in a crash (0.1 s) or by braking (3 s). Expected
# average forces 100 kN and 3.3 kN. Exercises: mechkit solve (F Δt = m Δv).
mechkit solve "F*dt = m*v" --for F --set "m=1000 kg,v=10 m/s,dt=0.1 s" --json
#> F1 = /numeric/0
mechkit solve "F*dt = m*v" --for F --set "m=1000 kg,v=10 m/s,dt=3 s" --json
#> F2 = /numeric/0
