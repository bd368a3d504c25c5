mod divergence;
mod events;
