//! Acceleration structures: one bottom-level structure per mesh, one top-level structure with an
//! identity-transform instance per mesh (instance custom index = mesh index).

use super::scene::{Scene, MESH_TABLE_WORDS, VERTEX_FLOATS};
use ash::vk;
use shader_proptest::{vulkan, Buffer, Error, Location, Object, Owner};

/// Byte alignment of the instance array's device address (Vulkan spec, VkAccelerationStructureGeometryInstancesDataKHR).
const INSTANCE_ALIGNMENT: u64 = 16;

/// Builds the scene's acceleration structures from the vertex and index buffers the shaders read
/// ([`Scene::vertex_floats`], [`Scene::indices`]) and returns the top-level one.
pub(super) fn build(
    owner: &mut Owner<'_>,
    scene: &Scene,
    vertices: &Buffer,
    indices: &Buffer,
) -> Result<vk::AccelerationStructureKHR, Error> {
    let loader = owner.acceleration.clone().ok_or_else(|| {
        Error::Setup(String::from(
            "acceleration structures are not enabled on this device",
        ))
    })?;
    let scratch_alignment = scratch_alignment(owner);
    let geometries = mesh_geometries(scene, vertices, indices);
    let mut blas = Vec::new();
    for (geometry, &count) in geometries.iter().zip(&primitive_counts(scene)) {
        let info = build_info(
            vk::AccelerationStructureTypeKHR::BOTTOM_LEVEL,
            std::slice::from_ref(geometry),
        );
        blas.push(Prepared::new(owner, &loader, info, count, scratch_alignment)?);
    }
    let instances = instance_buffer(owner, &blas)?;
    let instance_geometry = [vk::AccelerationStructureGeometryKHR::default()
        .geometry_type(vk::GeometryTypeKHR::INSTANCES)
        .geometry(vk::AccelerationStructureGeometryDataKHR {
            instances: vk::AccelerationStructureGeometryInstancesDataKHR::default().data(
                vk::DeviceOrHostAddressConstKHR {
                    device_address: instances.address,
                },
            ),
        })];
    let tlas_info = build_info(vk::AccelerationStructureTypeKHR::TOP_LEVEL, &instance_geometry);
    let tlas = Prepared::new(owner, &loader, tlas_info, blas.len() as u32, scratch_alignment)?;
    let readers = owner.shader_stages();
    owner.submit(|device, command_buffer| {
        // SAFETY: recording into a command buffer in the recording state; every address and
        // handle is alive until the owner drops.
        unsafe {
            let infos: Vec<_> = blas.iter().map(|b| b.info).collect();
            let ranges: Vec<[vk::AccelerationStructureBuildRangeInfoKHR; 1]> =
                blas.iter().map(|b| [b.range]).collect();
            let range_refs: Vec<&[_]> = ranges.iter().map(|r| &r[..]).collect();
            loader.cmd_build_acceleration_structures(command_buffer, &infos, &range_refs);
            let built = vk::MemoryBarrier::default()
                .src_access_mask(vk::AccessFlags::ACCELERATION_STRUCTURE_WRITE_KHR)
                .dst_access_mask(vk::AccessFlags::ACCELERATION_STRUCTURE_READ_KHR);
            let stage = vk::PipelineStageFlags::ACCELERATION_STRUCTURE_BUILD_KHR;
            device.cmd_pipeline_barrier(
                command_buffer,
                stage,
                stage,
                vk::DependencyFlags::empty(),
                &[built],
                &[],
                &[],
            );
            loader.cmd_build_acceleration_structures(command_buffer, &[tlas.info], &[&[tlas.range]]);
            let to_shaders = vk::MemoryBarrier::default()
                .src_access_mask(vk::AccessFlags::ACCELERATION_STRUCTURE_WRITE_KHR)
                .dst_access_mask(vk::AccessFlags::ACCELERATION_STRUCTURE_READ_KHR);
            device.cmd_pipeline_barrier(
                command_buffer,
                stage,
                readers,
                vk::DependencyFlags::empty(),
                &[to_shaders],
                &[],
                &[],
            );
        }
    })?;
    Ok(tlas.handle)
}

/// `minAccelerationStructureScratchOffsetAlignment` of the device.
fn scratch_alignment(owner: &Owner<'_>) -> u64 {
    let mut acceleration = vk::PhysicalDeviceAccelerationStructurePropertiesKHR::default();
    owner.gpu.extended_properties(&mut acceleration);
    u64::from(acceleration.min_acceleration_structure_scratch_offset_alignment)
}

/// Triangles per mesh.
fn primitive_counts(scene: &Scene) -> Vec<u32> {
    scene
        .meshes
        .iter()
        .map(|mesh| mesh.triangle_count() as u32)
        .collect()
}

/// One opaque triangle geometry per mesh, reading positions (the first three floats of each
/// vertex) and 32-bit indices at the mesh's offsets in the shared buffers.
fn mesh_geometries(
    scene: &Scene,
    vertices: &Buffer,
    indices: &Buffer,
) -> Vec<vk::AccelerationStructureGeometryKHR<'static>> {
    let stride = (VERTEX_FLOATS * 4) as u64;
    let table = scene.mesh_table();
    scene
        .meshes
        .iter()
        .zip(table.chunks_exact(MESH_TABLE_WORDS))
        .map(|(mesh, entry)| {
            let triangles = vk::AccelerationStructureGeometryTrianglesDataKHR::default()
                .vertex_format(vk::Format::R32G32B32_SFLOAT)
                .vertex_data(vk::DeviceOrHostAddressConstKHR {
                    device_address: vertices.address + u64::from(entry[1]) * stride,
                })
                .vertex_stride(stride)
                .max_vertex(mesh.vertices.len() as u32 - 1)
                .index_type(vk::IndexType::UINT32)
                .index_data(vk::DeviceOrHostAddressConstKHR {
                    device_address: indices.address + u64::from(entry[0]) * 4,
                });
            vk::AccelerationStructureGeometryKHR::default()
                .geometry_type(vk::GeometryTypeKHR::TRIANGLES)
                .flags(vk::GeometryFlagsKHR::OPAQUE)
                .geometry(vk::AccelerationStructureGeometryDataKHR { triangles })
        })
        .collect()
}

fn build_info<'a>(
    ty: vk::AccelerationStructureTypeKHR,
    geometries: &'a [vk::AccelerationStructureGeometryKHR<'a>],
) -> vk::AccelerationStructureBuildGeometryInfoKHR<'a> {
    vk::AccelerationStructureBuildGeometryInfoKHR::default()
        .ty(ty)
        .flags(vk::BuildAccelerationStructureFlagsKHR::PREFER_FAST_TRACE)
        .mode(vk::BuildAccelerationStructureModeKHR::BUILD)
        .geometries(geometries)
}

/// An acceleration structure created with its storage and scratch, and its build recorded in
/// `info` and `range`, ready to be built.
struct Prepared<'a> {
    handle: vk::AccelerationStructureKHR,
    address: vk::DeviceAddress,
    info: vk::AccelerationStructureBuildGeometryInfoKHR<'a>,
    range: vk::AccelerationStructureBuildRangeInfoKHR,
}

impl<'a> Prepared<'a> {
    fn new(
        owner: &mut Owner<'_>,
        loader: &ash::khr::acceleration_structure::Device,
        info: vk::AccelerationStructureBuildGeometryInfoKHR<'a>,
        primitives: u32,
        scratch_alignment: u64,
    ) -> Result<Prepared<'a>, Error> {
        let mut sizes = vk::AccelerationStructureBuildSizesInfoKHR::default();
        // SAFETY: a plain query with a valid build info; objects are handed to the owner.
        unsafe {
            loader.get_acceleration_structure_build_sizes(
                vk::AccelerationStructureBuildTypeKHR::DEVICE,
                &info,
                &[primitives],
                &mut sizes,
            );
            let storage = owner.buffer(
                sizes.acceleration_structure_size,
                vk::BufferUsageFlags::ACCELERATION_STRUCTURE_STORAGE_KHR,
                Location::Device,
                1,
            )?;
            let create = vk::AccelerationStructureCreateInfoKHR::default()
                .buffer(storage.buffer)
                .size(sizes.acceleration_structure_size)
                .ty(info.ty);
            let handle = loader
                .create_acceleration_structure(&create, None)
                .map_err(vulkan("vkCreateAccelerationStructureKHR"))?;
            owner.keep(handle, Object::AccelerationStructure);
            let scratch = owner.buffer(
                sizes.build_scratch_size,
                vk::BufferUsageFlags::STORAGE_BUFFER,
                Location::Device,
                scratch_alignment,
            )?;
            let address = loader.get_acceleration_structure_device_address(
                &vk::AccelerationStructureDeviceAddressInfoKHR::default().acceleration_structure(handle),
            );
            Ok(Prepared {
                handle,
                address,
                info: info
                    .dst_acceleration_structure(handle)
                    .scratch_data(vk::DeviceOrHostAddressKHR {
                        device_address: scratch.address,
                    }),
                range: vk::AccelerationStructureBuildRangeInfoKHR::default().primitive_count(primitives),
            })
        }
    }
}

/// A host buffer of one identity-transform instance per bottom-level structure, custom index =
/// mesh index, visible to every ray (mask 0xff), hit group 0, back faces not culled.
fn instance_buffer(owner: &mut Owner<'_>, blas: &[Prepared<'_>]) -> Result<Buffer, Error> {
    let identity = vk::TransformMatrixKHR {
        matrix: [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0],
    };
    let flags = vk::GeometryInstanceFlagsKHR::TRIANGLE_FACING_CULL_DISABLE.as_raw() as u8;
    let instances: Vec<vk::AccelerationStructureInstanceKHR> = blas
        .iter()
        .enumerate()
        .map(|(index, b)| vk::AccelerationStructureInstanceKHR {
            transform: identity,
            instance_custom_index_and_mask: vk::Packed24_8::new(index as u32, 0xff),
            instance_shader_binding_table_record_offset_and_flags: vk::Packed24_8::new(0, flags),
            acceleration_structure_reference: vk::AccelerationStructureReferenceKHR {
                device_handle: b.address,
            },
        })
        .collect();
    // SAFETY: VkAccelerationStructureInstanceKHR is a 64-byte plain-data struct without padding.
    let bytes = unsafe {
        std::slice::from_raw_parts(
            instances.as_ptr().cast::<u8>(),
            std::mem::size_of_val(instances.as_slice()),
        )
    };
    owner.upload(
        bytes,
        vk::BufferUsageFlags::ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_KHR,
        INSTANCE_ALIGNMENT,
    )
}
