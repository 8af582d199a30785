// The wireframe tutorial's coverage formula with none of ray-footprint's guards: no clamps, the
// built-in smoothstep on the edges as given (undefined where they coincide), the stipple as a
// branch, no-dash and zero-repeat cases left to the hardware. A yardstick for the function_costs
// benchmark, which compiles it in the same kernel as rf_process_wireframe; not a function to use.
float unguarded_process_wireframe(RfWireframeSettings settings, float3 barycentrics, float3 deltas) {
    float e = max(max(barycentrics.x, barycentrics.y), barycentrics.z);
    float factor = lerp(settings.thickness_var.x, settings.thickness_var.y, 1.0 - sin(e * 3.14159265358979));
    float3 pixel_deltas = settings.screen_space ? deltas : (float3)1.0;
    float3 start = pixel_deltas * (0.5 * settings.thickness * factor);
    float3 end = start + pixel_deltas * (settings.thickness * settings.smoothing);
    float3 ramp = smoothstep(start, end, barycentrics);
    float coverage = 1.0 - min(min(ramp.x, ramp.y), ramp.z);
    if (settings.stipple) {
        float repeats = float(settings.stipple_repeats);
        float pattern = frac((e + 0.5 * settings.stipple_length / repeats) * repeats);
        coverage *= pattern < settings.stipple_length ? 1.0 : 0.0;
    }
    return coverage;
}
