# c13-B12: how high above its base is the centre of mass of a uniform equilateral triangle
# of side 2b? Expected Y_cm/b = 1/√3 = 0.57735 (the book's B.12), by the exact formula for a
# triangular plate (examples/bodies/triangle_plate.toml, lengths in b); and checked with the
# pixels of a triangle with b = 150 px on a 400 × 400 image (examples/data/triangle_b150.png,
# written by examples/data/shapes.py), where the rasterised triangle gives 0.577303.
# Exercises: mechkit com BODYFILE (a triangle shape), and mechkit com IMAGE (R+G+B < 1.5
# marks the body) with the scale b = 1 (150 px = 1 m) and the origin at the centre of the
# base, so Y_cm is in units of b.
mechkit com examples/bodies/triangle_plate.toml --json
#> exact = /centre_of_mass/1
mechkit com examples/data/triangle_b150.png --scale "150 px = 1 m" --origin "200, 400" --json
#> pixel_estimate = /centre_of_mass/1
