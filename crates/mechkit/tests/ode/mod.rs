mod adaptive;
mod banded;
mod convergence;
mod energy_behaviour;
mod fsal;
mod long_runs;
mod orders;
mod testset;
