mod diagram;
mod ledger;
