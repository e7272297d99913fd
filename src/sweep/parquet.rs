//! `runs.parquet`: the runs table in a typed columnar file (polars), for users who load sweeps
//! into dataframes. The CSV is the record (its cells are the exact text every check compares);
//! the Parquet file is written from it with each column typed: booleans, then integers, then
//! floats where every cell of the column reads as one, text otherwise; an empty cell is null.

use std::path::Path;

use polars::prelude::*;

use crate::error::{Error, Result};
use crate::table::{Table, write_atomic};

/// A column of text cells as a typed polars column.
fn column(name: &str, cells: &[&str]) -> Column {
    let present = || cells.iter().filter(|c| !c.is_empty());
    fn opt<'s>(c: &&'s str) -> Option<&'s str> {
        (!c.is_empty()).then_some(*c)
    }
    let name = PlSmallStr::from(name);
    if present().count() > 0 && present().all(|c| *c == "true" || *c == "false") {
        let v: Vec<Option<bool>> = cells.iter().map(|c| opt(c).map(|c| c == "true")).collect();
        Column::new(name, v)
    } else if present().count() > 0 && present().all(|c| c.parse::<i64>().is_ok()) {
        let v: Vec<Option<i64>> = cells.iter().map(|c| opt(c).map(|c| c.parse().unwrap())).collect();
        Column::new(name, v)
    } else if present().count() > 0 && present().all(|c| c.parse::<f64>().is_ok()) {
        let v: Vec<Option<f64>> = cells.iter().map(|c| opt(c).map(|c| c.parse().unwrap())).collect();
        Column::new(name, v)
    } else {
        let v: Vec<Option<&str>> = cells.iter().map(opt).collect();
        Column::new(name, v)
    }
}

/// The table as a polars frame.
pub fn frame(t: &Table) -> Result<DataFrame> {
    let columns = t
        .header
        .iter()
        .enumerate()
        .map(|(k, name)| {
            let cells: Vec<&str> = t.rows.iter().map(|r| r.get(k).map_or("", String::as_str)).collect();
            column(name, &cells)
        })
        .collect();
    DataFrame::new(t.rows.len(), columns).map_err(|e| Error::input("<parquet>", e.to_string()))
}

/// Write `t` to `path` as Parquet, atomically.
pub fn write(t: &Table, path: &Path) -> Result<()> {
    let mut df = frame(t)?;
    let mut bytes = Vec::new();
    ParquetWriter::new(&mut bytes).finish(&mut df).map_err(|e| Error::io(path, std::io::Error::other(e.to_string())))?;
    write_atomic(path, &bytes)
}

/// Read a Parquet file (tests and `merge` checks).
pub fn read(path: &Path) -> Result<DataFrame> {
    let f = std::fs::File::open(path).map_err(|e| Error::io(path, e))?;
    ParquetReader::new(f).finish().map_err(|e| Error::io(path, std::io::Error::other(e.to_string())))
}
