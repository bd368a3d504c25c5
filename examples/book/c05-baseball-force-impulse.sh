# c05: a bat's force on a 0.145 kg baseball, measured every 40.4 us for 4 ms (100 samples,
# examples/data/baseballforce.d). Expected impulse J = ∫F dt = 13.612 N s, exit speed J/m =
# 93.87 m/s from rest, peak force 5464.1 N at t = 1.8586 ms. Exercises: mechkit impulse on a
# force-time file (trapezoids over the samples, the impulse-momentum theorem).
mechkit impulse examples/data/baseballforce.d --mass "0.145 kg" -o out/book/baseball-impulse --json
#> J_Ns = /impulse
#> v_exit_mps = /delta_v
#> F_max_N = /peak/f
#> t_Fmax_s = /peak/x
