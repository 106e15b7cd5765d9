//! rosbridge's `png` compression: an outgoing operation's JSON text stored as the pixels
//! of an 8-bit RGB PNG image, base64-encoded in `{"op": "png", "data": …}`. roslibjs asks
//! for it (`compression: "png"`) to shrink large messages; it decodes the image and
//! parses the pixel bytes as JSON.
//!
//! Layout (what rosbridge's clients expect): the UTF-8 bytes fill the pixels row by row,
//! three per pixel; the image is about square — `width = floor(sqrt(n / 3))` (at least
//! 1), `height = ceil(n / 3 / width)` — and the tail is padded with `\n`, which JSON
//! parsers skip as whitespace.

use base64::Engine;
use base64::engine::general_purpose::STANDARD as BASE64;

/// The PNG image holding `text`.
pub fn encode(text: &[u8]) -> Vec<u8> {
    let n = text.len();
    let width = ((n as f64 / 3.0).sqrt().floor() as usize).max(1);
    let height = n.div_ceil(3).div_ceil(width).max(1);
    let mut pixels = Vec::with_capacity(width * height * 3);
    pixels.extend_from_slice(text);
    pixels.resize(width * height * 3, b'\n');
    let mut out = Vec::with_capacity(n / 2 + 64);
    {
        let mut enc = png::Encoder::new(&mut out, width as u32, height as u32);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        enc.set_compression(png::Compression::Fast);
        let mut w = enc
            .write_header()
            .expect("writing a PNG header to memory cannot fail");
        w.write_image_data(&pixels)
            .expect("the pixel buffer matches the header's size");
    }
    out
}

/// The `png` operation carrying `json` (an operation's JSON text).
pub fn op(json: &[u8]) -> String {
    let data = BASE64.encode(encode(json));
    let mut s = String::with_capacity(data.len() + 24);
    s.push_str(r#"{"op":"png","data":""#);
    s.push_str(&data);
    s.push_str(r#""}"#);
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn decode(png_bytes: &[u8]) -> (u32, u32, Vec<u8>) {
        let dec = png::Decoder::new(std::io::Cursor::new(png_bytes));
        let mut r = dec.read_info().unwrap();
        let mut buf = vec![0; r.output_buffer_size()];
        let info = r.next_frame(&mut buf).unwrap();
        buf.truncate(info.buffer_size());
        (info.width, info.height, buf)
    }

    #[test]
    fn the_pixels_are_the_text_padded_with_newlines() {
        for text in [
            &b"{}"[..],
            br#"{"op":"publish","topic":"/a","msg":{"data":1}}"#,
            &[b'x'; 10_000][..],
        ] {
            let (w, h, px) = decode(&encode(text));
            assert_eq!(px.len(), (w * h * 3) as usize);
            assert_eq!(&px[..text.len()], text);
            assert!(px[text.len()..].iter().all(|b| *b == b'\n'));
            assert!(w <= h + 1, "about square: {w}x{h}");
        }
    }

    #[test]
    fn the_op_is_json_with_base64_png() {
        let op = op(br#"{"op":"publish"}"#);
        let v: serde_json::Value = serde_json::from_str(&op).unwrap();
        assert_eq!(v["op"], "png");
        let png = BASE64.decode(v["data"].as_str().unwrap()).unwrap();
        let (_, _, px) = decode(&png);
        let text = String::from_utf8(px).unwrap();
        let back: serde_json::Value = serde_json::from_str(text.trim_end()).unwrap();
        assert_eq!(back["op"], "publish");
    }
}
