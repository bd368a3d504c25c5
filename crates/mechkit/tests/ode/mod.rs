mod adaptive;
mod convergence;
mod energy_behaviour;
mod fsal;
