mod errors;
mod examples;
mod run;
