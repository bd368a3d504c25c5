mod convergence;
mod energy_behaviour;
