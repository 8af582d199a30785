// Relative luminance of a linear Rec. 709 colour.
fn luminance(colour: vec3<f32>) -> f32 {
    return dot(colour, vec3<f32>(0.2126, 0.7152, 0.0722));
}

// Reinhard's tone map, c / (1 + c) per channel.
fn tone_map(colour: vec3<f32>) -> vec3<f32> {
    return colour / (vec3<f32>(1.0) + colour);
}
