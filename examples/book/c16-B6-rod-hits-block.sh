# c16-B6: a rod (M = 1 kg, L = 1 m) hinged at its top end is released from the horizontal
# (θ0 = 90°) and at the bottom strikes a block of mass m = M/3 at its lower end. Expected
# ω0 = sqrt((3g/L)(1 − cos θ0)) = 5.42494 rad/s; elastic: the rod stops and the block takes
# ω0 L = 5.42494 m/s; perfectly inelastic: both move on at ω0 L/(1 + 3m/M) = 2.71247 m/s.
# Exercises: mechkit rigid-collide (ω0 by energy conservation, the impact written about the
# hinge: angular momentum about the pivot conserved).
mechkit rigid-collide --rod --mass "1 kg" --length "1 m" --pivot-at end --release-angle "90 deg" --g "9.81 m/s^2" --block-mass 0.3333333333333333 --restitution elastic --json
#> omega0 = /omega0
#> v_block_elastic = /block/velocity_after/0
mechkit rigid-collide --rod --mass "1 kg" --length "1 m" --pivot-at end --release-angle "90 deg" --g "9.81 m/s^2" --block-mass 0.3333333333333333 --restitution perfectly-inelastic --json
#> v_inelastic = /block/velocity_after/0
