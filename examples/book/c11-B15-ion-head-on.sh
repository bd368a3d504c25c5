# c11-B15: an ion (m = 1) starts at x = b = 1 moving head-on toward a repulsive centre with
# U = C/x (C = 1) at v0 = 2.5. Expected closest approach x1 = 0.242424 and speed far away
# v_inf = 2.872281. Exercises: mechkit potential (the work-energy theorem: turning point
# where U = E, and v(x) = sqrt(2(E - U)/m) far away).
mechkit potential "C/x" --range 0.01:1e9 --set C=1 --mass 1 --x0 1 --v0 2.5 --at 1e15 -o out/book/c11-B15-ion --json
#> x1 = /motion/left_turn
#> v_inf = /at/0/speed
