% The course's loop in Octave: the feather with quadratic drag, Euler-Cromer. 10^6 steps
% (1 s of the fall; the terminal speed is reached in 0.2 s): at ~10 µs per step, 10^7 would
% take 100 s per round, and the cost per step does not depend on the count.
g = 9.8; Dmg = 4.0; dt = 1e-6; n = 1e6;
x = 2.4; v = 0;
tic;
for i = 1:n
  a = -g - g*Dmg*v*abs(v);
  v = v + a*dt;
  x = x + v*dt;
end
t = toc;
printf("feather\tOctave loop\t%.2f\t%.6f\n", t/n*1e9, v);
xs = linspace(0, 1, 1e7); ys = xs.^2;
tic; value = trapz(xs, ys); t = toc;
printf("trapz\tOctave trapz\t%.3f\t%.9f\n", t/1e7*1e9, value);
