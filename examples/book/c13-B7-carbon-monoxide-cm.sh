# c13-B7: the centre of mass of a carbon monoxide molecule (bond length 112.8 pm), measured
# from the oxygen atom. Expected 48.37 pm. Exercises: mechkit com (atomic mass units, the
# result in pm).
mechkit com --mass "15.999 u" --at "0 pm" --mass "12.011 u" --at "112.8 pm" --in pm --json
#> answer = /centre_of_mass_in_unit/0
