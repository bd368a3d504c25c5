mod adaptive_runs;
mod divergence;
mod event_cases;
mod events;
mod fused;
mod issue_011_zeno_ball_falls_through;
mod issue_021_cancel_one_run;
mod issue_021_events_never_missed;
