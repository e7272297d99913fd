//! Little-endian encoding of checkpoints: integers and floats by their bits, so that what is
//! read back is exactly what was written. A damaged or foreign file is an input error on the
//! field `checkpoint`.

use crate::error::{Error, Result};

/// An input error about a checkpoint's bytes.
pub(crate) fn bad(message: String) -> Error {
    Error::input("checkpoint", message)
}

/// Appends values to a byte buffer.
pub(crate) struct Writer(pub Vec<u8>);

impl Writer {
    pub fn bytes(&mut self, b: &[u8]) {
        self.0.extend_from_slice(b);
    }
    pub fn u64(&mut self, v: u64) {
        self.bytes(&v.to_le_bytes());
    }
    pub fn u32(&mut self, v: u32) {
        self.bytes(&v.to_le_bytes());
    }
    pub fn f64(&mut self, v: f64) {
        self.u64(v.to_bits());
    }
    pub fn f64s(&mut self, vs: &[f64]) {
        vs.iter().for_each(|&v| self.f64(v));
    }
}

/// Reads values back in the order they were written; every read checks the length.
pub(crate) struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    pub fn new(bytes: &'a [u8]) -> Self {
        Reader { bytes, at: 0 }
    }
    fn left(&self) -> usize {
        self.bytes.len() - self.at
    }
    pub fn slice(&mut self, n: usize) -> Result<&'a [u8]> {
        if n > self.left() {
            return Err(bad(format!("truncated: {} bytes, needed {} more at byte {}", self.bytes.len(), n, self.at)));
        }
        let s = &self.bytes[self.at..self.at + n];
        self.at += n;
        Ok(s)
    }
    pub fn take<const N: usize>(&mut self) -> Result<[u8; N]> {
        Ok(self.slice(N)?.try_into().expect("length checked"))
    }
    pub fn u64(&mut self) -> Result<u64> {
        Ok(u64::from_le_bytes(self.take()?))
    }
    pub fn u32(&mut self) -> Result<u32> {
        Ok(u32::from_le_bytes(self.take()?))
    }
    pub fn f64(&mut self) -> Result<f64> {
        Ok(f64::from_bits(self.u64()?))
    }
    pub fn f64s<const N: usize>(&mut self) -> Result<[f64; N]> {
        let mut out = [0.0; N];
        for v in &mut out {
            *v = self.f64()?;
        }
        Ok(out)
    }
    /// A length that must equal `expected` (the scene's count of the same thing).
    pub fn count(&mut self, what: &str, expected: usize) -> Result<()> {
        let n = self.u64()?;
        if n != expected as u64 {
            return Err(bad(format!("{n} {what}, the model has {expected}")));
        }
        Ok(())
    }
    /// A length of items of `per_item` bytes each that must fit in what is left.
    pub fn len(&mut self, what: &str, per_item: usize) -> Result<usize> {
        let n = self.u64()?;
        if n.saturating_mul(per_item as u64) > self.left() as u64 {
            return Err(bad(format!("truncated: {n} {what} do not fit in the {} bytes left", self.left())));
        }
        Ok(n as usize)
    }
    /// Nothing may follow the last value.
    pub fn finish(self) -> Result<()> {
        match self.left() {
            0 => Ok(()),
            n => Err(bad(format!("{n} bytes after the end of the state"))),
        }
    }
}
