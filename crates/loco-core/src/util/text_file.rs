//! Input files as text: every file loco reads (vehicle TOML, profiles, measured track, curve
//! sections, study and samples files) is UTF-8, and anything else is refused with the file, the
//! line and the byte position of the first byte that is not, instead of an operating-system
//! message or a character decoded wrongly.
//!
//! A UTF-8 byte-order mark (EF BB BF, which some spreadsheet programs write at the start of a
//! CSV) is accepted explicitly: it is skipped, so it is never read as part of a header or a
//! first data row. A UTF-16 or UTF-32 byte-order mark is refused naming the encoding.

use std::path::Path;

use crate::error::{FileKind, LocoError, Result};

/// The UTF-8 byte-order mark.
const UTF8_BOM: &[u8] = &[0xEF, 0xBB, 0xBF];

/// The content of the file at `path` (a file of `kind`), checked to be UTF-8 text. A file that
/// cannot be read is [`LocoError::Io`]; one that is not UTF-8 is [`LocoError::Parse`] of `kind`.
pub fn read_text(path: &Path, kind: FileKind) -> Result<String> {
    let bytes = std::fs::read(path).map_err(|e| LocoError::Io {
        path: path.display().to_string(),
        reason: e.to_string(),
    })?;
    decode(bytes, &path.display().to_string(), kind)
}

/// `bytes`, the content of the file `label` (a file of `kind`), as text: a UTF-8 byte-order
/// mark skipped, any other encoding refused naming the line and byte offset of the first byte
/// that is not UTF-8, and a file holding a NUL byte refused as binary.
pub fn decode(bytes: Vec<u8>, label: &str, kind: FileKind) -> Result<String> {
    let other_bom = [
        (&[0x00, 0x00, 0xFE, 0xFF][..], "UTF-32 (big-endian)"),
        (&[0xFF, 0xFE, 0x00, 0x00][..], "UTF-32 (little-endian)"),
        (&[0xFE, 0xFF][..], "UTF-16 (big-endian)"),
        (&[0xFF, 0xFE][..], "UTF-16 (little-endian)"),
    ];
    if let Some((_, name)) = other_bom.iter().find(|(bom, _)| bytes.starts_with(bom)) {
        return Err(LocoError::parse(
            kind,
            label,
            1,
            format!("the file is {name} text; loco reads UTF-8: save it as UTF-8"),
        ));
    }
    let body = if bytes.starts_with(UTF8_BOM) {
        bytes[UTF8_BOM.len()..].to_vec()
    } else {
        bytes
    };
    // A NUL byte is valid UTF-8 but no text file holds one: the file is binary.
    if let Some(offset) = body.iter().position(|&b| b == 0) {
        let line = body[..offset].iter().filter(|&&b| b == b'\n').count() + 1;
        return Err(LocoError::parse(
            kind,
            label,
            line,
            format!("binary data: a NUL byte at byte offset {offset}; loco reads UTF-8 text"),
        ));
    }
    String::from_utf8(body).map_err(|e| {
        let offset = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        let line = bytes[..offset].iter().filter(|&&b| b == b'\n').count() + 1;
        LocoError::parse(
            kind,
            label,
            line,
            format!(
                "not UTF-8 text: byte 0x{:02X} at byte offset {offset} is not valid UTF-8 (Latin-1 or \
                 another encoding?); loco reads UTF-8: save the file as UTF-8",
                bytes[offset]
            ),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utf8_passes_a_bom_is_skipped_and_other_encodings_are_named() {
        let ok = decode(
            "a = 1\n# é\n".as_bytes().to_vec(),
            "v.toml",
            FileKind::Vehicle,
        );
        assert_eq!(ok.unwrap(), "a = 1\n# é\n");
        let bom = decode(
            b"\xEF\xBB\xBFkind,length_m\n".to_vec(),
            "c.csv",
            FileKind::Track,
        );
        assert_eq!(bom.unwrap(), "kind,length_m\n");
        // Latin-1 'é' on the second line, at byte offset 8.
        let e = decode(b"a = 1\n# \xE9\n".to_vec(), "v.toml", FileKind::Vehicle).unwrap_err();
        assert!(matches!(
            e,
            LocoError::Parse {
                kind: FileKind::Vehicle,
                line: 2,
                ..
            }
        ));
        let text = e.to_string();
        assert!(text.starts_with("v.toml:2: not UTF-8 text"), "{text}");
        assert!(text.contains("byte 0xE9 at byte offset 8"), "{text}");
        let e = decode(b"\xFF\xFEa\x00".to_vec(), "t.csv", FileKind::Track).unwrap_err();
        assert!(e.to_string().contains("UTF-16 (little-endian)"), "{e}");
        let e = decode(b"\x00\x01\xFF".to_vec(), "w.txt", FileKind::Profile).unwrap_err();
        assert!(e.to_string().contains("binary data"), "{e}");
    }

    #[test]
    fn a_missing_file_is_an_io_error() {
        let e = read_text(Path::new("/nonexistent/v.toml"), FileKind::Vehicle).unwrap_err();
        assert!(matches!(e, LocoError::Io { .. }), "{e}");
    }
}
