//! What the references of every section share: how a reference compares the mirror's components
//! with its own, within bounds that take the mirror's f32 rounding from the record's interval
//! enclosure (its width encloses both the exact value of the function's formula on the same
//! inputs and the mirror's result), adding what the reference itself leaves open: the error of its
//! central differences and, where it starts from exact geometry, the rounding of the inputs.

use crate::degenerate::parts;
use crate::reference::Deviation;
use glam::DVec3;
use shader_proptest::interval::Interval;
use shader_proptest::Value;

/// The widths of an enclosure's intervals: bounds of the mirror's rounding, component by component.
pub(crate) fn widths(enclosure: &[Interval]) -> Vec<f64> {
    enclosure
        .iter()
        .map(|interval| interval.hi - interval.lo)
        .collect()
}

/// The worst of the components of `got` (as the harness lists them) against `expected`, each within
/// `bound(index)`.
pub(crate) fn components<R: Value>(got: R, expected: &[f64], bound: impl Fn(usize) -> f64) -> Deviation {
    let got = parts(got);
    assert_eq!(got.len(), expected.len(), "one expected value per component");
    Deviation::worst(
        got.iter()
            .zip(expected)
            .enumerate()
            .map(|(index, (&g, &e))| Deviation::within(f64::from(g), e, bound(index))),
    )
}

/// The components of vectors as a list, each vector followed by `pad` zeros (a `RayDiff`'s
/// padding: 1; `Derivatives3`: 0).
pub(crate) fn listed(vectors: &[DVec3], pad: usize) -> Vec<f64> {
    vectors
        .iter()
        .flat_map(|v| v.to_array().into_iter().chain(std::iter::repeat_n(0.0, pad)))
        .collect()
}
