// The width of a pinhole camera's pixel cone, of spread angle `spread`, at distance `t`.
float footprint(float spread, float t) {
    return rf_width_at(rf_pinhole_ray_cone(spread), t);
}
