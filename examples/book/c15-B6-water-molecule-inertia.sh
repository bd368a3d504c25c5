# c15-B6: the moment of inertia of a water molecule (O at the origin, two H at distance a,
# angle 104.5°) about the axis perpendicular to its plane, through the O atom and through the
# centre of mass. Expected I_O = 2 u a², I_cm = 1.92 u a² (1.9167). Exercises: mechkit inertia
# on a body file of point masses (the moment about an axis; the parallel-axis theorem).
mechkit inertia examples/bodies/water.toml --axis "0, 0, 1" --json
#> I_O = /axis/moment
#> I_cm = /inertia_cm/2/2
