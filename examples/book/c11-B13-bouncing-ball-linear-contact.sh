# c11-B13: a 0.1 kg ball of radius 0.1 m dropped from centre height 1 m onto a floor that acts
# as a spring k = 1000 N/m. Expected compression dy = sqrt((2 m g/k)(h - R)) = 0.042021 m.
# Exercises: mechkit solve (k dy^2/2 = m g (h - R), the positive root).
mechkit solve "k*dy^2/2 = m*g*(h - R)" --for dy --set "k=1000 N/m,m=0.1 kg,g=9.81 m/s^2,h=1 m,R=0.1 m" --json
#> answer = /numeric/1
