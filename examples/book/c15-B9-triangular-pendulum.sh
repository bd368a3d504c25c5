# c15-B9: two point masses m on massless rods of length L form an equilateral triangle with the
# pivot O. Expected: I_O = 2 m L^2; released with one rod horizontal, it swings through the
# bottom at omega = sqrt(sqrt(3) g/(2L)) = 2.91474 rad/s with v_cm = 2.52424 m/s (the free
# flight after release is c15-B9-triangular-pendulum.toml). Exercises: a rigid body of point
# parts hinged at a pivot ([[rigid_body]]), gravity's torque, a stop condition on theta.
mechkit run examples/rigid/triangular_pendulum.toml --json --out out/c15-B9
#> I_O = /observables/I_O
#> omega = /observables/omega
#> v_cm = /observables/v_cm
