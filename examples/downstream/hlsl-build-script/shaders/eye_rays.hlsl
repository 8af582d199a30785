// A user's HLSL compute shader: the world direction of the eye ray through every pixel, from the
// camera's inverse view and projection matrices, with ray-footprint's ray-differential module
// brought in by #include (its directory on the compiler's include path).

#include "ray_diff.hlsl"

// The camera as the host writes it: glam's column-major Mat4 lands in HLSL's default column_major
// float4x4, so m[r][c] is row r, column c of the matrix, as the module expects.
struct Camera {
    float4x4 view_inv;
    float4x4 proj_inv;
    float2 image_size;
    float2 pad;
};

[[vk::binding(0, 0)]] StructuredBuffer<Camera> camera;
// Per pixel, row by row: the eye ray's direction (w is 0).
[[vk::binding(1, 0)]] RWStructuredBuffer<float4> directions;

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint count;
    uint stride;
    directions.GetDimensions(count, stride);
    if (id.x >= count) {
        return;
    }
    Camera view = camera[0];
    uint width = (uint)view.image_size.x;
    float2 pixel = float2(id.x % width, id.x / width);
    float3 direction = rf_eye_ray_direction_from_matrices(pixel, view.image_size, view.view_inv, view.proj_inv);
    directions[id.x] = float4(direction, 0.0);
}
