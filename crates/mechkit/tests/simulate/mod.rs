mod adaptive_runs;
mod divergence;
mod event_cases;
mod events;
mod fused;
