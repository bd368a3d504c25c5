# c14-B5: an unbalanced wheel turns with ω(t) = 2.5 cos(t/(2 s)) rad/s; ω and α at t = π s.
# Expected θ = 5 sin(t/2 s) rad, ω(π s) = 0, α(π s) = −1.25 rad/s². Exercises: mechkit rotation
# --omega (θ by symbolic integration, α by the derivative).
mechkit rotation --omega "w0*cos(t/T)" --set "w0=2.5,T=2 s" --at pi --json
#> omega = /at/0/omega
#> alpha = /at/0/alpha
