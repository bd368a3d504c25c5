mod errors;
mod floor;
mod head_on;
mod setup;
