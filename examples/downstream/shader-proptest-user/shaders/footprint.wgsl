// The width of a pinhole camera's pixel cone, of spread angle `spread`, at distance `t`.
fn footprint(spread: f32, t: f32) -> f32 {
    return rf_width_at(rf_pinhole_ray_cone(spread), t);
}
