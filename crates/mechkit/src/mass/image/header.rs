//! The width and height a PNG or JPEG file claims, read from its header by hand, before any
//! decoder sees the file: a decoder applies limits of its own first and reports a 2147483647 × 1
//! PNG as "Memory limit exceeded" (or a JPEG past its maximum width as a decode error), where
//! mechkit's message is the size limit.

/// The `(width, height)` in the IHDR chunk of a PNG file (bytes 16..24, after the 8-byte
/// signature, the chunk's length and its type); `None` if the file is too short or the
/// first chunk is not IHDR.
pub(super) fn png_size(bytes: &[u8]) -> Option<(u32, u32)> {
    if bytes.get(12..16)? != b"IHDR" {
        return None;
    }
    let word = |at: usize| Some(u32::from_be_bytes(bytes.get(at..at + 4)?.try_into().ok()?));
    Some((word(16)?, word(20)?))
}

/// The `(width, height)` in the first start-of-frame segment (SOF0–SOF15 but DHT, JPG and
/// DAC) of a JPEG file; `None` if there is none before the image data or the segments run past
/// the end. A height of 0 (defined later by a DNL segment) is returned as it is.
pub(super) fn jpeg_size(bytes: &[u8]) -> Option<(u32, u32)> {
    let mut at = 2; // after SOI
    loop {
        if *bytes.get(at)? != 0xFF {
            return None;
        }
        let marker = *bytes.get(at + 1)?;
        match marker {
            // fill bytes before a marker
            0xFF => at += 1,
            // markers without a segment: TEM, RSTn, SOI
            0x01 | 0xD0..=0xD8 => at += 2,
            // end of image or start of scan before any frame header
            0xD9 | 0xDA => return None,
            _ => {
                let length = usize::from(u16::from_be_bytes([
                    *bytes.get(at + 2)?,
                    *bytes.get(at + 3)?,
                ]));
                if matches!(marker, 0xC0..=0xCF) && !matches!(marker, 0xC4 | 0xC8 | 0xCC) {
                    let half =
                        |i: usize| Some(u16::from_be_bytes([*bytes.get(i)?, *bytes.get(i + 1)?]));
                    // length, precision, then height and width
                    let (height, width) = (half(at + 5)?, half(at + 7)?);
                    return Some((u32::from(width), u32::from(height)));
                }
                if length < 2 {
                    return None;
                }
                at += 2 + length;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{jpeg_size, png_size};

    #[test]
    fn a_png_header_gives_its_size() {
        let mut png = b"\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR".to_vec();
        png.extend(2_147_483_647u32.to_be_bytes());
        png.extend(1u32.to_be_bytes());
        assert_eq!(png_size(&png), Some((2_147_483_647, 1)));
        assert_eq!(png_size(&png[..20]), None);
    }

    #[test]
    fn a_jpeg_header_gives_its_size_after_other_segments() {
        // SOI, APP0 of 4 bytes, SOF0: length 11, precision 8, height 300, width 65535
        let jpeg = [
            0xFF, 0xD8, 0xFF, 0xE0, 0, 4, 1, 2, 0xFF, 0xC0, 0, 11, 8, 1, 44, 0xFF, 0xFF, 1,
        ];
        assert_eq!(jpeg_size(&jpeg), Some((65535, 300)));
        assert_eq!(jpeg_size(&jpeg[..12]), None);
        assert_eq!(jpeg_size(&[0xFF, 0xD8, 0xFF, 0xD9]), None);
    }
}
