//! Tables out: CSV written atomically (a temporary file in the same folder, synced, then
//! renamed), so a run that fails or is killed never leaves a half-written table and never
//! clobbers the previous one.

use std::io::Write;
use std::path::{Path, PathBuf};

use crate::error::{Error, Result};

pub mod row;

pub use row::Cell;

/// A table: a header and rows of already formatted cells.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Table {
    /// Column names (each carrying its unit).
    pub header: Vec<String>,
    /// Rows.
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// CSV text of the table.
    pub fn to_csv(&self) -> Result<Vec<u8>> {
        let mut w = csv::Writer::from_writer(Vec::new());
        w.write_record(&self.header).map_err(|e| Error::io("<csv>", e))?;
        for r in &self.rows {
            w.write_record(r).map_err(|e| Error::io("<csv>", e))?;
        }
        w.into_inner().map_err(|e| Error::io("<csv>", e.error()))
    }

    /// Write as CSV to `path`, atomically.
    pub fn write_csv(&self, path: &Path) -> Result<()> {
        write_atomic(path, &self.to_csv()?)
    }

    /// Read a CSV file written by `write_csv`.
    pub fn read_csv(path: &Path) -> Result<Table> {
        let mut r = csv::Reader::from_path(path).map_err(|e| Error::io(path, e))?;
        let header = r.headers().map_err(|e| Error::io(path, e))?.iter().map(String::from).collect();
        let mut rows = Vec::new();
        for rec in r.records() {
            rows.push(rec.map_err(|e| Error::io(path, e))?.iter().map(String::from).collect());
        }
        Ok(Table { header, rows })
    }

    /// Index of a column.
    pub fn column(&self, name: &str) -> Option<usize> {
        self.header.iter().position(|h| h == name)
    }

    /// The cell of column `name` in row `row`.
    pub fn get(&self, row: usize, name: &str) -> Option<&str> {
        Some(self.rows.get(row)?.get(self.column(name)?)?.as_str())
    }

    /// A one-row table of a serialisable struct (see [`row`]).
    pub fn from_row<T: serde::Serialize>(value: &T) -> Result<Table> {
        Table::from_rows(std::slice::from_ref(value))
    }

    /// A table of serialisable structs, one row each; every row must have the same columns.
    pub fn from_rows<T: serde::Serialize>(values: &[T]) -> Result<Table> {
        let mut t = Table::default();
        for v in values {
            let cells = row::cells(v).map_err(|e| Error::input("<table>", e))?;
            if t.header.is_empty() {
                t.header = cells.iter().map(|c| c.0.clone()).collect();
            } else if t.header.len() != cells.len() || t.header.iter().zip(&cells).any(|(h, c)| *h != c.0) {
                return Err(Error::input("<table>", "rows with different columns"));
            }
            t.rows.push(cells.iter().map(|c| c.1.text()).collect());
        }
        Ok(t)
    }
}

/// Write `bytes` to `path` via a synced temporary file and a rename.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    }
    let tmp: PathBuf = {
        let mut name = path.file_name().map(|n| n.to_os_string()).unwrap_or_default();
        // Unique per write, so two writers in one process never share a temporary file.
        static WRITES: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
        let k = WRITES.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        name.push(format!(".tmp-{}-{k}", std::process::id()));
        path.with_file_name(name)
    };
    let result = (|| -> std::io::Result<()> {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(bytes)?;
        f.sync_all()?;
        std::fs::rename(&tmp, path)
    })();
    if let Err(e) = result {
        let _ = std::fs::remove_file(&tmp);
        return Err(Error::io(path, e));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_and_no_temporary_left() {
        let dir = std::env::temp_dir().join(format!("demsweep-table-{}", std::process::id()));
        let path = dir.join("t.csv");
        let t = Table { header: vec!["a_m".into(), "b_n".into()], rows: vec![vec!["1".into(), "2.5".into()]] };
        t.write_csv(&path).unwrap();
        assert_eq!(Table::read_csv(&path).unwrap(), t);
        let names: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names.len(), 1, "{names:?}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
