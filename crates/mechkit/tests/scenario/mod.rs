mod errors;
mod examples;
mod rigid;
mod run;
mod sweep;
