# c12-B12: a pendulum bob of mass m, released from height L, hits a block of mass M = 2m at
# rest elastically at the bottom, where its speed is sqrt(2gL). Expected velocities after, in
# units of sqrt(2gL): bob -1/3, block 2/3 (the rebound height L/9 follows from the bob's speed;
# computing it needs the pendulum's constrained motion, a later issue). Exercises: mechkit
# collide (elastic, 1-D), velocities in units of sqrt(2gL).
mechkit collide --m1 1 --v1 1 --m2 2 --v2 0 --restitution elastic --json
#> v_bob = /v1/0
#> V_block = /v2/0
