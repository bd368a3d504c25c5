# c14-B4: a flywheel turns by θ(t) = c1 t/t1 + c2 (t/t2)² with c1 = 1 rad, t1 = 1 s, c2 = 2 rad,
# t2 = 2 s; its angular velocity and acceleration at t = 1 s. Expected ω = c1/t1 + 2 c2 t/t2² =
# 2 rad/s, α = 2 c2/t2² = 1 rad/s². Exercises: mechkit rotation --theta (symbolic derivatives,
# checked by Ridders' extrapolation).
mechkit rotation --theta "c1*t/t1 + c2*(t/t2)^2" --set "c1=1,t1=1 s,c2=2,t2=2 s" --at "1 s" --json
#> omega = /at/0/omega
#> alpha = /at/0/alpha
