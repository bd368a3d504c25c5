# c12-B5: a 0.43 kg ball kicked from rest to 20 m/s; the foot touches it for 0.1 s, or for
# 0.05 s. Expected momentum change = impulse = 8.6 kg m/s, average forces 86 N and 172 N.
# Exercises: mechkit solve (Δp = m Δv, J = F_avg Δt).
mechkit solve "dp = m*v" --for dp --set "m=0.43 kg,v=20 m/s" --json
#> dp = /numeric/0
#> J = /numeric/0
mechkit solve "F*dt = m*v" --for F --set "m=0.43 kg,v=20 m/s,dt=0.1 s" --json
#> F_avg_c = /numeric/0
mechkit solve "F*dt = m*v" --for F --set "m=0.43 kg,v=20 m/s,dt=0.05 s" --json
#> F_avg_d = /numeric/0
