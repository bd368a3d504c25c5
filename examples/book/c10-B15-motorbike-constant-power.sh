# c10-B15: a 200 kg motorbike starts from rest with constant engine power 20 kW. Expected at
# t = 5 s: v = 31.623 m/s, a = 3.1623 m/s^2, x = 105.41 m. Exercises: mechkit power
# (constant-power motion v = sqrt(2Pt/m), x = (2/3) sqrt(2P/m) t^(3/2)).
mechkit power --power "20 kW" --mass "200 kg" --at "5 s" --out out/book/motorbike --json
#> v = /at/0/v
#> a = /at/0/a
#> x = /at/0/x
