//! The case strategy that records of every section use: a ray cone.

use crate::strategy::{angle, scalar};
use proptest::prelude::*;
use ray_footprint::ray_cone::RayCone;

/// A cone: a width from [`scalar`], a spread angle from [`angle`].
pub(crate) fn ray_cone() -> BoxedStrategy<RayCone> {
    (scalar(), angle())
        .prop_map(|(width, spread_angle)| RayCone { width, spread_angle })
        .boxed()
}
