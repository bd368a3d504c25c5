# c10-B12: a heart does 70.53 kJ of work in a day. Expected average power 0.816 W.
# Exercises: mechkit power (average power W/t), with units on the command line.
mechkit power --work "70.53 kJ" --time "24 h" --json
#> answer = /average_power
