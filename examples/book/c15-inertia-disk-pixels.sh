# c15: the moment of inertia of a uniform disk about its axis, I = Σ mᵢ rᵢ², summed over the
# pixels of a disk of radius R = 150 px (examples/data/disk_r150.png, written by
# examples/data/shapes.py). Expected I/(M R²) = 1/2; the rasterised disk gives 0.500023
# with each pixel's own inertia (0.500015 with the pixels as points). Exercises: mechkit com
# IMAGE with R = 1 (150 px = 1 m) and M = 1 kg, so I_zz about the centre of mass is I/(M R²).
mechkit com examples/data/disk_r150.png --scale "150 px = 1 m" --total-mass "1 kg" --json
#> exact = /inertia_cm/zz
#> pixel = /inertia_cm/zz
