mod adaptive_runs;
mod divergence;
mod event_cases;
mod events;
mod fused;
mod issue_011_zeno_ball_falls_through;
