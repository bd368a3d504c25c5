mod impacts;
mod properties;
