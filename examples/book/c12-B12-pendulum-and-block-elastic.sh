# c12-B12: a pendulum bob of mass m, released from height L, hits a block of mass M = 2m at
# rest elastically at the bottom, where its speed is sqrt(2gL). Expected, in units of
# sqrt(2gL): bob -1/3, block 2/3 after; the bob swings back up to h = L/9.
# Exercises: mechkit collide (elastic, 1-D) and --g, the height a speed turns into
# (h = v²/2g). Units: L = 1 and g = 1/2, so that sqrt(2gL) = 1 and heights are in L.
mechkit collide --m1 1 --v1 1 --m2 2 --v2 0 --restitution elastic --g 0.5 --json
#> v_bob = /v1/0
#> V_block = /v2/0
#> h_over_L = /rise1
