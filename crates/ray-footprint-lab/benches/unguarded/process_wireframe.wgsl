// The wireframe tutorial's coverage formula with none of ray-footprint's guards: no clamps, the
// built-in smoothstep on the edges as given (undefined where they coincide), the stipple as a
// branch, no-dash and zero-repeat cases left to the hardware. A yardstick for the function_costs
// benchmark, which compiles it in the same kernel as rf_process_wireframe; not a function to use.
fn unguarded_process_wireframe(settings: RfWireframeSettings, barycentrics: vec3<f32>, deltas: vec3<f32>) -> f32 {
    let e = max(max(barycentrics.x, barycentrics.y), barycentrics.z);
    let factor = mix(settings.thickness_var.x, settings.thickness_var.y, 1.0 - sin(e * 3.14159265358979));
    let pixel_deltas = select(vec3<f32>(1.0), deltas, settings.screen_space);
    let start = pixel_deltas * (0.5 * settings.thickness * factor);
    let end = start + pixel_deltas * (settings.thickness * settings.smoothing);
    let ramp = smoothstep(start, end, barycentrics);
    var coverage = 1.0 - min(min(ramp.x, ramp.y), ramp.z);
    if settings.stipple {
        let repeats = f32(settings.stipple_repeats);
        let pattern = fract((e + 0.5 * settings.stipple_length / repeats) * repeats);
        coverage *= select(0.0, 1.0, pattern < settings.stipple_length);
    }
    return coverage;
}
