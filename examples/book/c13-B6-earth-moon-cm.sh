# c13-B6: where is the centre of mass of the Earth-Moon system, in Earth radii from the
# Earth's centre? Expected 0.7328 R_E with the standard constants (d = 384,400 km); the
# book's 0.763 follows from d = 4.0e8 m (0.7625). Exercises: mechkit com (point masses, the
# result expressed in a length unit, here the Earth's radius 6371 km).
mechkit com --mass "5.972e24 kg" --at "0 m" --mass "7.342e22 kg" --at "384400 km" --in "6371 km" --json
#> standard_constants = /centre_of_mass_in_unit/0
mechkit com --mass "5.972e24 kg" --at "0 m" --mass "7.342e22 kg" --at "4.0e8 m" --in "6371 km" --json
#> with_d_4e8 = /centre_of_mass_in_unit/0
#> book = /centre_of_mass_in_unit/0
