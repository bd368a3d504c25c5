mod convergence;
mod functions;
mod tennis_ball;
