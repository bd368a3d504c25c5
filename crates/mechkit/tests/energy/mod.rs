mod diagram;
mod ledger;
mod power;
