# c15-B5: a rod (1 kg, 1 m) with a solid sphere (0.5 kg, radius 10 cm) centred on each end:
# the moment of inertia about the centre, perpendicular to the rod. Expected
# mL²/12 + 2(2/5)MR² + 2M(L/2)² = 0.337333 kg m². Exercises: mechkit inertia on a composite
# body file (standard shapes, placed and turned; the parallel-axis theorem for every part).
mechkit inertia examples/bodies/rod_two_spheres.toml --axis "0, 0, 1" --json
#> answer = /axis/moment
