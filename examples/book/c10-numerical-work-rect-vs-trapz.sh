# c10: the work W = ∫_0^{b/4} -F0 sin(2 pi x/b) dx (F0 = b = 1) by left rectangles, midpoints
# and trapezoids with 10 and 100 intervals (book Fig. 10.3). Expected exact -0.159155; left
# -0.146328 / -0.157902, midpoint -0.159319, trapezoid -0.158828 / -0.159152. Exercises:
# mechkit integrate --method (the fixed rules, each with its error against the closed form).
mechkit integrate "-F0*sin(2*pi*x/b)" --from 0 --to b/4 --set F0=1,b=1 --method left,midpoint,trapezoid --n 10,100 --json
#> exact = /definite/closed_form
#> left_n10 = /rules/0/value
#> left_n100 = /rules/1/value
#> mid_n10 = /rules/2/value
#> trapz_n10 = /rules/4/value
#> trapz_n100 = /rules/5/value
# The same force sampled at 101 points (examples/data/forcedata.d, written by forcedata.py)
# and integrated as data, like the course's trapz over forcedata.d:
mechkit work examples/data/forcedata.d --method left --json
#> left_n100 = /work
mechkit work examples/data/forcedata.d --method trapezoid -o out/book/work-trapezoid --json
#> trapz_n100 = /work
