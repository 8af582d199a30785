// Relative luminance of a linear Rec. 709 colour.
float luminance(vec3 colour) {
    return dot(colour, vec3(0.2126, 0.7152, 0.0722));
}

// Reinhard's tone map, c / (1 + c) per channel.
vec3 tone_map(vec3 colour) {
    return colour / (vec3(1.0) + colour);
}
