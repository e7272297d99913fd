//! The pieces of a self-contained HTML page: escaped text, tables, images inlined as data URLs
//! (base64, RFC 4648), so the page needs no network, script or font to be read.

use crate::table::Table;

/// `text` with `& < > "` escaped.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            c => out.push(c),
        }
    }
    out
}

/// Standard base64 with padding (RFC 4648 §4).
pub fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [chunk[0], *chunk.get(1).unwrap_or(&0), *chunk.get(2).unwrap_or(&0)];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(ALPHABET[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// A PNG as an inline image with a caption.
pub fn figure(png: &[u8], caption: &str) -> String {
    format!("<figure><img alt=\"{0}\" src=\"data:image/png;base64,{1}\"><figcaption>{0}</figcaption></figure>\n", escape(caption), base64(png))
}

/// `columns` of `table` (those it has, in this order; all when empty) as an HTML table, at most
/// `max_rows` rows (the rest counted below it).
pub fn table(t: &Table, columns: &[&str], max_rows: usize) -> String {
    let keep: Vec<usize> = if columns.is_empty() { (0..t.header.len()).collect() } else { columns.iter().filter_map(|c| t.column(c)).collect() };
    let mut out = String::from("<table>\n<tr>");
    for &k in &keep {
        out += &format!("<th>{}</th>", escape(&t.header[k]));
    }
    out += "</tr>\n";
    for row in t.rows.iter().take(max_rows) {
        out += "<tr>";
        for &k in &keep {
            out += &format!("<td>{}</td>", escape(row.get(k).map_or("", String::as_str)));
        }
        out += "</tr>\n";
    }
    out += "</table>\n";
    if t.rows.len() > max_rows {
        out += &format!("<p class=\"note\">{} more rows in the CSV.</p>\n", t.rows.len() - max_rows);
    }
    out
}

/// The page's style: plain, printable, no external font.
pub const STYLE: &str = "body{font-family:sans-serif;max-width:72em;margin:1.5em auto;padding:0 1em;color:#222}\
h1{font-size:1.5em;margin-bottom:.2em}h2{font-size:1.2em;border-bottom:1px solid #ccc;margin-top:1.6em}h2.failed{color:#a00}\
.answer{font-size:1.15em;background:#f3f6fa;border:1px solid #c9d6e6;padding:.6em 1em}\
.answer b{font-size:1.1em}table{border-collapse:collapse;font-size:.85em;margin:.5em 0}\
td,th{border:1px solid #ccc;padding:.15em .5em;text-align:right}th{background:#eee}\
img{max-width:100%}pre{background:#f6f6f6;padding:.6em;overflow-x:auto;font-size:.85em}\
.note{color:#666;font-size:.9em}figure{margin:1em 0}figcaption{color:#555;font-size:.9em}";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_gives_the_rfc_4648_test_vectors() {
        for (plain, coded) in [("", ""), ("f", "Zg=="), ("fo", "Zm8="), ("foo", "Zm9v"), ("foob", "Zm9vYg=="), ("fooba", "Zm9vYmE="), ("foobar", "Zm9vYmFy")] {
            assert_eq!(base64(plain.as_bytes()), coded, "{plain:?}");
        }
        assert_eq!(base64(&[0xff, 0xfe, 0x00]), "//4A");
    }

    #[test]
    fn escaping_leaves_no_markup() {
        assert_eq!(escape("<a href=\"x\">&</a>"), "&lt;a href=&quot;x&quot;&gt;&amp;&lt;/a&gt;");
    }
}
