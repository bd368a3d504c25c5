# c13-ex13.2.4: the course's image method: the pixels with R+G+B < 1.5 are the body, and
# their mean position (pixel centres, x = column, y = row) is its centre of mass. On a black
# disk of radius 150 px centred at (200, 200) in a white 400 × 400 image
# (examples/data/disk_r150.png, written by examples/data/shapes.py) the expected centre is
# (200, 200) px (199.5 with integer indices instead of pixel centres). Exercises: mechkit
# com IMAGE with the default threshold.
mechkit com examples/data/disk_r150.png --threshold 1.5 --channel sum --json
#> x = /pixel_centre_of_mass/0
#> y = /pixel_centre_of_mass/1
