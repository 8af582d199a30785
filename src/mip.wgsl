// One mip level from the level above, rendered over the whole level (one triangle that covers it):
// each texel the box filter of the level above over the exact area it covers, as
// ray_footprint::mip computes it on the CPU. textureLoad of an sRGB texture decodes to linear
// light and the sRGB target encodes, so colours are averaged as light.

@group(0) @binding(0) var level_above: texture_2d<f32>;

@vertex
fn covering_triangle(@builtin(vertex_index) index: u32) -> @builtin(position) vec4<f32> {
    let corner = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    return vec4<f32>(corner * vec2<f32>(4.0, -4.0) + vec2<f32>(-1.0, 1.0), 0.0, 1.0);
}

// The texels of a row of `above` texels that texel `index` of a row of `below` covers: the first,
// and one past the last. Texel `index` spans [index, index + 1) * above / below, in units of
// 1 / below: [start, start + above).
fn covered_texels(index: u32, above: u32, below: u32) -> vec2<u32> {
    let start = index * above;
    return vec2<u32>(start / below, min((start + above + below - 1u) / below, above));
}

// The share of texel `index` of a row of `below` that texel `texel` of a row of `above` makes up.
fn share(texel: u32, index: u32, above: u32, below: u32) -> f32 {
    let start = index * above;
    let covered = min(start + above, (texel + 1u) * below) - max(start, texel * below);
    return f32(covered) / f32(above);
}

@fragment
fn box_filter(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let size_above = textureDimensions(level_above);
    let size = max(size_above / 2u, vec2<u32>(1u));
    let texel = vec2<u32>(position.xy);
    let columns = covered_texels(texel.x, size_above.x, size.x);
    let rows = covered_texels(texel.y, size_above.y, size.y);
    var sum = vec4<f32>(0.0);
    for (var y = rows.x; y < rows.y; y++) {
        let row_share = share(y, texel.y, size_above.y, size.y);
        for (var x = columns.x; x < columns.y; x++) {
            sum += row_share * share(x, texel.x, size_above.x, size.x) * textureLoad(level_above, vec2<u32>(x, y), 0);
        }
    }
    return sum;
}
