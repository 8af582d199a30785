//! Textures made in code, each with a full mip chain down to 1 x 1.

/// Width and height of both textures, in texels (11 mip levels).
pub const TEXTURE_SIZE: u32 = 1024;
/// Side of a checker square, in texels of level 0: level 5 has one texel per square, level 6 and
/// above are the uniform average.
pub const CHECKER_SQUARE: u32 = 32;

/// One colour per mip level for [`mip_colours`] (RTG Fig. 20-9): red, orange, yellow, green,
/// cyan, blue, violet, magenta, white, grey, black.
pub const LEVEL_COLOURS: [[u8; 4]; 11] = [
    [230, 40, 40, 255],
    [240, 140, 30, 255],
    [235, 220, 40, 255],
    [60, 190, 60, 255],
    [40, 200, 210, 255],
    [40, 80, 230, 255],
    [140, 60, 220, 255],
    [220, 60, 200, 255],
    [245, 245, 245, 255],
    [128, 128, 128, 255],
    [20, 20, 20, 255],
];

/// A square RGBA8 texture and its mip levels, level 0 first, texels row by row.
#[derive(Clone, Debug)]
pub struct MipChain {
    /// Width and height of level 0.
    pub size: u32,
    /// Level `i` is `size >> i` texels square.
    pub levels: Vec<Vec<[u8; 4]>>,
}

impl MipChain {
    /// `Ok` when the chain is square, a power of two wide, and has every level down to 1 x 1 with
    /// `(size >> i)^2` texels at level `i`; else what is wrong.
    pub fn validate(&self) -> Result<(), String> {
        if !self.size.is_power_of_two() {
            return Err(format!("size {} is not a power of two", self.size));
        }
        if self.levels.len() != level_count(self.size) {
            let expected = level_count(self.size);
            return Err(format!(
                "{} levels, a size of {} needs {expected}",
                self.levels.len(),
                self.size
            ));
        }
        for (i, level) in self.levels.iter().enumerate() {
            let side = (self.size >> i) as usize;
            if level.len() != side * side {
                return Err(format!(
                    "level {i} has {} texels, not {side} x {side}",
                    level.len()
                ));
            }
        }
        Ok(())
    }
}

/// A light and dark checkerboard with squares of `square` texels, box-filtered down to 1 x 1.
pub fn checker(size: u32, square: u32) -> MipChain {
    let texel = |i: u32| {
        let (x, y) = (i % size / square, i / size / square);
        if (x + y) % 2 == 0 {
            [230, 225, 210, 255]
        } else {
            [35, 40, 55, 255]
        }
    };
    mip_chain(size, (0..size * size).map(texel).collect())
}

/// A checkerboard of `coarse`-texel squares, light and dark, each filled with a finer checker of
/// `fine`-texel squares of two shades of its colour: detail at two scales. Level
/// `log2(2 * fine)` and above have lost the fine checker and keep the coarse one up to level
/// `log2(coarse)`; box-filtered down to 1 x 1.
pub fn two_scale_checker(size: u32, coarse: u32, fine: u32) -> MipChain {
    let texel = |i: u32| {
        let (x, y) = (i % size, i / size);
        let light = (x / coarse + y / coarse).is_multiple_of(2);
        let bright = (x / fine + y / fine).is_multiple_of(2);
        match (light, bright) {
            (true, true) => [240, 235, 220, 255],
            (true, false) => [150, 150, 145, 255],
            (false, true) => [95, 100, 120, 255],
            (false, false) => [25, 30, 45, 255],
        }
    };
    mip_chain(size, (0..size * size).map(texel).collect())
}

/// `texture` enlarged to `size` texels square (a power of two, at least the texture's size): each
/// texel of its level 0 repeated over a square block, and the chain rebuilt below it. The same
/// image in texture coordinates, with `size^2` texels at level 0 for a level-0 sampler to fetch
/// from: the large textures of `mode_costs --texture-size`.
pub fn enlarged(texture: &MipChain, size: u32) -> MipChain {
    let block = size / texture.size;
    let level0 = (0..size * size)
        .map(|i| {
            let (x, y) = (i % size / block, i / size / block);
            texture.levels[0][(y * texture.size + x) as usize]
        })
        .collect();
    mip_chain(size, level0)
}

/// `level0` (`size` x `size` texels) and every level below it down to 1 x 1, each the
/// box-filtered level above.
fn mip_chain(size: u32, level0: Vec<[u8; 4]>) -> MipChain {
    let mut levels = vec![level0];
    while levels.len() < level_count(size) {
        let previous = levels.last().expect("level 0 exists");
        levels.push(downsample(previous, size >> (levels.len() - 1)));
    }
    MipChain { size, levels }
}

/// A texture whose level `i` is filled with [`LEVEL_COLOURS`]`[i]`, so a sample's colour tells
/// which levels it blended.
pub fn mip_colours(size: u32) -> MipChain {
    let levels = (0..level_count(size))
        .map(|i| vec![LEVEL_COLOURS[i % LEVEL_COLOURS.len()]; ((size >> i) * (size >> i)) as usize])
        .collect();
    MipChain { size, levels }
}

/// `log2(size) + 1`: the levels from `size` down to 1.
fn level_count(size: u32) -> usize {
    (u32::BITS - size.leading_zeros()) as usize
}

/// The next level of a `size` x `size` level: each texel the rounded mean of a 2 x 2 block.
fn downsample(level: &[[u8; 4]], size: u32) -> Vec<[u8; 4]> {
    let half = size / 2;
    let at = |x: u32, y: u32| level[(y * size + x) as usize];
    (0..half * half)
        .map(|i| {
            let (x, y) = (2 * (i % half), 2 * (i / half));
            let block = [at(x, y), at(x + 1, y), at(x, y + 1), at(x + 1, y + 1)];
            [0, 1, 2, 3].map(|c| ((block.iter().map(|t| u32::from(t[c])).sum::<u32>() + 2) / 4) as u8)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A texture enlarged four times is the same image: its level 2 and every level below are the
    /// original's level 0 and below, texel for texel (a block of equal texels averages to itself).
    #[test]
    fn an_enlarged_texture_has_the_original_below_its_new_levels() {
        let original = two_scale_checker(64, 16, 4);
        let large = enlarged(&original, 256);
        assert_eq!(large.validate(), Ok(()));
        assert_eq!(large.levels.len(), original.levels.len() + 2);
        assert_eq!(large.levels[2..], original.levels[..]);
    }
}
