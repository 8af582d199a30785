//! `abi_bytes`: arbitrary bytes as every struct that crosses the CPU/GPU boundary.
//!
//! - Checked casts ([`bytemuck::try_from_bytes`], [`bytemuck::try_cast_slice`],
//!   [`bytemuck::try_pod_read_unaligned`]) succeed exactly when the length and, for references, the
//!   alignment allow, and never panic; a value read from bytes gives back the same bytes.
//! - `WireframeSettingsIo` to `WireframeSettings` and back: every float kept bit for bit, every flag
//!   `!= 0`, `pack` writes exactly 0 or 1, and a second round trip changes nothing. `validate`
//!   accepts exactly what its documentation says.
//! - Packed ray cones: `pack(unpack(p)) == p` for finite halves; infinite halves pack to `±F16_MAX`;
//!   packing a finite cone never gives an infinite half, and re-packing its unpacked form is exact.

use super::words::Words;
use bytemuck::Pod;
use ray_footprint::abi::{HitPayload, RayConePushConstants, WireframePushConstants};
use ray_footprint::ray_cone::{pack_ray_cone, unpack_ray_cone, PackedRayCone, RayCone, F16_MAX};
use ray_footprint::ray_diff::RayDiff;
use ray_footprint::wireframe::{WireframeSettings, WireframeSettingsIo, MAX_LINE_THICKNESS};

/// The `abi_bytes` target.
pub fn abi_bytes(data: &[u8]) -> Result<(), String> {
    casts::<RayCone>("RayCone", data)?;
    casts::<PackedRayCone>("PackedRayCone", data)?;
    casts::<HitPayload>("HitPayload", data)?;
    casts::<RayConePushConstants>("RayConePushConstants", data)?;
    casts::<WireframeSettingsIo>("WireframeSettingsIo", data)?;
    casts::<WireframePushConstants>("WireframePushConstants", data)?;
    casts::<RayDiff>("RayDiff", data)?;
    let mut words = Words::new(data);
    let io: WireframeSettingsIo = bytemuck::pod_read_unaligned(&words.bytes(32));
    settings_round_trip(io)?;
    packed_cone_round_trip(PackedRayCone(words.u32()))?;
    cone_round_trip(RayCone {
        width: words.f32(),
        spread_angle: words.f32(),
    })
}

fn check(holds: bool, what: impl FnOnce() -> String) -> Result<(), String> {
    if holds {
        Ok(())
    } else {
        Err(what())
    }
}

/// The checked casts of `data` (and of each of its suffixes shorter than the struct's alignment,
/// so that misaligned starts are tried too) as `T`.
fn casts<T: Pod>(name: &str, data: &[u8]) -> Result<(), String> {
    for skip in 0..std::mem::align_of::<T>().min(data.len() + 1) {
        cast_at::<T>(name, &data[skip..])?;
    }
    Ok(())
}

fn cast_at<T: Pod>(name: &str, data: &[u8]) -> Result<(), String> {
    let size = std::mem::size_of::<T>();
    let aligned = data.as_ptr().cast::<T>().is_aligned();
    let one = bytemuck::try_from_bytes::<T>(data);
    check(one.is_ok() == (aligned && data.len() == size), || {
        format!(
            "{name}: try_from_bytes of {} bytes (aligned: {aligned}) gave {:?}",
            data.len(),
            one.err()
        )
    })?;
    let many = bytemuck::try_cast_slice::<u8, T>(data);
    check(
        many.is_ok() == (aligned && data.len().is_multiple_of(size)),
        || {
            format!(
                "{name}: try_cast_slice of {} bytes (aligned: {aligned}) gave {:?}",
                data.len(),
                many.err()
            )
        },
    )?;
    let read = bytemuck::try_pod_read_unaligned::<T>(data);
    check(read.is_ok() == (data.len() == size), || {
        format!(
            "{name}: try_pod_read_unaligned of {} bytes gave {:?}",
            data.len(),
            read.err()
        )
    })?;
    crate_conversions::<T>(name, data, aligned)?;
    for chunk in data.chunks_exact(size) {
        let value: T = bytemuck::pod_read_unaligned(chunk);
        check(bytemuck::bytes_of(&value) == chunk, || {
            format!(
                "{name}: bytes {chunk:02x?} read back as {:02x?}",
                bytemuck::bytes_of(&value)
            )
        })?;
    }
    Ok(())
}

/// [`ray_footprint::abi::from_bytes`], [`ray_footprint::abi::vec_from_bytes`] and [`ray_footprint::abi::slice_from_bytes`]
/// succeed exactly when the length (and, in place, the alignment) allow, give back the same bytes,
/// and otherwise hold the struct, its size or alignment and what the bytes are. (How the errors
/// read is `tests/bad_input.rs`'s business: rendering every error here made the target six times
/// slower.)
fn crate_conversions<T: Pod>(name: &str, data: &[u8], aligned: bool) -> Result<(), String> {
    use ray_footprint::abi::{from_bytes, slice_from_bytes, vec_from_bytes};
    let size = std::mem::size_of::<T>();
    let whole = data.len().is_multiple_of(size);
    let one = from_bytes::<T>(data);
    check(one.is_ok() == (data.len() == size), || {
        format!("{name}: from_bytes of {} bytes gave {:?}", data.len(), one.err())
    })?;
    let many = vec_from_bytes::<T>(data);
    let in_place = slice_from_bytes::<T>(data);
    check(
        many.is_ok() == whole && in_place.is_ok() == (whole && aligned),
        || {
            format!(
                "{name}: vec_from_bytes / slice_from_bytes of {} bytes (aligned: {aligned}) gave {:?} / {:?}",
                data.len(),
                many.as_ref().err(),
                in_place.err()
            )
        },
    )?;
    if let Ok(values) = &many {
        check(bytemuck::cast_slice::<T, u8>(values) == data, || {
            format!("{name}: vec_from_bytes changed the bytes")
        })?;
    }
    for error in [one.err(), many.err(), in_place.err()].into_iter().flatten() {
        check(error_is_exact::<T>(name, data, error), || {
            format!(
                "{name}: the error {error:?} ({error}) does not describe {} bytes",
                data.len()
            )
        })?;
    }
    Ok(())
}

/// Whether `error` holds the struct's name, size or alignment and what `data` is.
fn error_is_exact<T>(name: &str, data: &[u8], error: ray_footprint::abi::BytesError) -> bool {
    use ray_footprint::abi::BytesError;
    let (size, align) = (std::mem::size_of::<T>(), std::mem::align_of::<T>());
    match error {
        BytesError::Length {
            structure,
            expected,
            actual,
        }
        | BytesError::NotWhole {
            structure,
            size: expected,
            actual,
        } => structure.ends_with(name) && (expected, actual) == (size, data.len()),
        BytesError::Misaligned {
            structure,
            align: needed,
            misalignment,
        } => {
            let expected = data.as_ptr() as usize % align;
            structure.ends_with(name) && (needed, misalignment) == (align, expected) && expected != 0
        }
    }
}

/// The float fields and flags of settings, floats by their bits: what a round trip must keep.
fn settings_bits(s: &WireframeSettings) -> ([u32; 5], bool, i32, bool) {
    let floats = [
        s.thickness_var.x,
        s.thickness_var.y,
        s.thickness,
        s.smoothing,
        s.stipple_length,
    ];
    (
        floats.map(f32::to_bits),
        s.stipple,
        s.stipple_repeats,
        s.screen_space,
    )
}

fn settings_round_trip(io: WireframeSettingsIo) -> Result<(), String> {
    let settings = io.unpack();
    let expected = WireframeSettingsIo {
        stipple: i32::from(io.stipple != 0),
        screen_space: i32::from(io.screen_space != 0),
        ..io
    };
    let packed = settings.pack();
    check(
        bytemuck::bytes_of(&packed) == bytemuck::bytes_of(&expected),
        || format!("unpack then pack of {io:?} gave {packed:?}, expected {expected:?}"),
    )?;
    let again = packed.unpack();
    check(settings_bits(&again) == settings_bits(&settings), || {
        format!("settings {settings:?} came back as {again:?}")
    })?;
    let via_from = WireframeSettingsIo::from(WireframeSettings::from(io));
    check(
        bytemuck::bytes_of(&via_from) == bytemuck::bytes_of(&packed),
        || format!("From conversions of {io:?} gave {via_from:?}, pack gave {packed:?}"),
    )?;
    validation(settings)
}

/// `validate` (and `try_new`) accept exactly the settings their documentation describes.
fn validation(s: WireframeSettings) -> Result<(), String> {
    let sizes = [s.thickness_var.x, s.thickness_var.y, s.thickness, s.smoothing];
    let acceptable = sizes.iter().all(|x| (0.0..=MAX_LINE_THICKNESS).contains(x))
        && (0.0..=1.0).contains(&s.stipple_length)
        && s.stipple_repeats >= 0;
    let verdict = s.validate();
    check(verdict.is_ok() == acceptable, || {
        format!("validate({s:?}) gave {verdict:?}")
    })?;
    if let Err(error) = verdict {
        check(error.to_string().contains(error.field()), || {
            format!("the message {error} does not name the field {}", error.field())
        })?;
    }
    let built = WireframeSettings::try_new(
        s.thickness,
        s.thickness_var,
        s.smoothing,
        s.stipple,
        s.stipple_length,
        s.stipple_repeats,
        s.screen_space,
    );
    let same_field = built.err().map(|e| e.field()) == verdict.err().map(|e| e.field());
    let same_value = built.ok().map(|b| settings_bits(&b)) == verdict.ok().map(|()| settings_bits(&s));
    check(same_field && same_value, || {
        format!("try_new and validate disagree on {s:?}")
    })
}

fn half_is_finite(bits: u16) -> bool {
    (bits >> 10) & 0x1f != 0x1f
}

fn halves(packed: PackedRayCone) -> [u16; 2] {
    [packed.0 as u16, (packed.0 >> 16) as u16]
}

fn packed_cone_round_trip(packed: PackedRayCone) -> Result<(), String> {
    let (cone, again) = (unpack_ray_cone(packed), pack_ray_cone(unpack_ray_cone(packed)));
    let unpacked_again = unpack_ray_cone(again);
    let values = [
        (cone.width, unpacked_again.width),
        (cone.spread_angle, unpacked_again.spread_angle),
    ];
    let pairs = halves(packed).into_iter().zip(halves(again)).zip(values);
    for (index, ((before, after), (value, value_again))) in pairs.enumerate() {
        let expected = if value.is_nan() {
            value_again.is_nan()
        } else if value.is_infinite() {
            value_again == F16_MAX.copysign(value)
        } else {
            after == before
        };
        check(expected, || {
            format!("half {index} of {packed:?} ({value}) packed again as {after:#06x}")
        })?;
    }
    Ok(())
}

fn cone_round_trip(cone: RayCone) -> Result<(), String> {
    let packed = pack_ray_cone(cone);
    let values = [cone.width, cone.spread_angle];
    for (index, (&value, &bits)) in values.iter().zip(&halves(packed)).enumerate() {
        check(value.is_nan() || half_is_finite(bits), || {
            format!("packing {cone:?} gave an infinite half {index}: {packed:?}")
        })?;
    }
    let unpacked = unpack_ray_cone(packed);
    if cone.width.is_finite() && cone.spread_angle.is_finite() {
        check(
            unpacked.width.is_finite() && unpacked.spread_angle.is_finite(),
            || format!("{cone:?} packed and unpacked as {unpacked:?}"),
        )?;
        let again = pack_ray_cone(unpacked);
        check(again == packed, || {
            format!("re-packing {unpacked:?} gave {again:?}, not {packed:?}")
        })?;
    }
    Ok(())
}
