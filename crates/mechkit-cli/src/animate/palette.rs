//! The GIF's fixed palette of 256 colours: a cube of 6 levels of red, green and blue (216
//! colours, six greys among them) and a ramp of 40 more greys (walls, text and its smoothed
//! edges stay grey, not tinted). Each pixel takes the nearest colour (in RGB distance): fast,
//! and the same picture always gives the same GIF.

/// The levels of each channel in the cube.
const LEVELS: u32 = 6;
/// The index of the first grey of the ramp, after the cube.
const FIRST_GREY: u32 = LEVELS * LEVELS * LEVELS;
/// The greys of the ramp: from 6 to 249, about 6 apart.
const GREYS: u32 = 40;

/// The palette as the GIF's colour table: `[r, g, b, r, g, b, …]`, 256 colours.
pub(super) fn table() -> Vec<u8> {
    let mut table = Vec::with_capacity(768);
    for r in 0..LEVELS {
        for g in 0..LEVELS {
            for b in 0..LEVELS {
                table.extend([level(r, LEVELS), level(g, LEVELS), level(b, LEVELS)]);
            }
        }
    }
    for k in 0..GREYS {
        table.extend([grey(k); 3]);
    }
    table
}

/// The index of the palette's colour nearest to `(r, g, b)`.
pub(super) fn nearest(r: u8, g: u8, b: u8) -> u8 {
    // in a cube the nearest point has each coordinate's nearest level
    let (ri, gi, bi) = (step(r, LEVELS), step(g, LEVELS), step(b, LEVELS));
    let cube = [level(ri, LEVELS), level(gi, LEVELS), level(bi, LEVELS)];
    let in_cube = (ri * LEVELS + gi) * LEVELS + bi;
    // the nearest grey is the one nearest the mean: on the ramp, one of those about it
    let mean = f64::from(u32::from(r) + u32::from(g) + u32::from(b)) / 3.0;
    let above = (mean * f64::from(GREYS + 1) / 255.0) as u32;
    let ramp = (above.saturating_sub(2)..=above)
        .filter(|&k| k < GREYS)
        .min_by_key(|&k| distance([r, g, b], [grey(k); 3]))
        .unwrap_or(0);
    if distance([r, g, b], [grey(ramp); 3]) < distance([r, g, b], cube) {
        (FIRST_GREY + ramp) as u8
    } else {
        in_cube as u8
    }
}

/// The ramp's `k`th grey: `255 (k + 1) / 41`, rounded.
fn grey(k: u32) -> u8 {
    (255.0 * f64::from(k + 1) / f64::from(GREYS + 1)).round() as u8
}

/// The `i`th of `levels` levels from 0 to 255.
fn level(i: u32, levels: u32) -> u8 {
    ((i * 255 + (levels - 1) / 2) / (levels - 1)) as u8
}

/// The nearest of `levels` levels to `v`.
fn step(v: u8, levels: u32) -> u32 {
    (u32::from(v) * (levels - 1) + 127) / 255
}

fn distance(a: [u8; 3], b: [u8; 3]) -> u32 {
    a.iter()
        .zip(b)
        .map(|(&x, y)| u32::from(x.abs_diff(y)).pow(2))
        .sum()
}

#[cfg(test)]
mod tests {
    use super::{distance, nearest, table};

    fn colour(table: &[u8], i: u8) -> [u8; 3] {
        let k = usize::from(i) * 3;
        [table[k], table[k + 1], table[k + 2]]
    }

    #[test]
    fn every_colour_maps_to_its_nearest_entry() {
        let table = table();
        assert_eq!(table.len(), 768);
        for c in (0..=255u8).step_by(17).flat_map(|r| {
            (0..=255u8)
                .step_by(15)
                .flat_map(move |g| (0..=255u8).step_by(51).map(move |b| [r, g, b]))
        }) {
            let got = distance(c, colour(&table, nearest(c[0], c[1], c[2])));
            let best = (0..=255u8)
                .map(|i| distance(c, colour(&table, i)))
                .min()
                .unwrap();
            assert_eq!(got, best, "{c:?}");
        }
        assert_eq!(colour(&table, nearest(255, 255, 255)), [255; 3]);
        assert_eq!(colour(&table, nearest(0, 0, 0)), [0; 3]);
        let grey = colour(&table, nearest(150, 150, 150));
        assert!(grey[0] == grey[1] && grey[1] == grey[2] && grey[0].abs_diff(150) <= 3);
    }
}
