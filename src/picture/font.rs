//! The one font of every picture: DejaVu Sans, embedded, so nothing from the system is needed.

use std::sync::Once;

use plotters::style::{FontStyle, register_font};

static FONT: Once = Once::new();

/// Register the font (once per process).
pub fn ensure() {
    FONT.call_once(|| {
        // The embedded font is valid by construction; a failure would only cost the labels.
        let _ = register_font("sans-serif", FontStyle::Normal, include_bytes!("../../assets/fonts/DejaVuSans.ttf"));
    });
}
