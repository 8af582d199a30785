//! Which method to use: per scene and method, the quality it gains over mip 0 (the quality lab's
//! `table.csv`) against the frame time it adds to mip 0 (the `mode_costs` bench's `--csv`, timed
//! on the same scenes), as a Markdown table and a plot ([`plot`]).
//!
//! The quality lab renders a method at one sample per pixel; `mode_costs` times the same scene,
//! view and texture through the mode's colour-only pipeline at the size and samples it was run
//! with. A scene without a mip-0 row (the wireframe's torus) has no gain over mip 0 and is left
//! out, and so is a method without a time.

use super::plots::{scatter_plot, ScatterPanel, ScatterPoint};
use super::LabError;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// One method on one scene: what it gains and what it costs.
#[derive(Clone, Debug, PartialEq)]
pub struct CostQuality {
    /// The scene.
    pub scene: String,
    /// The method (a mode's name).
    pub method: String,
    /// PSNR over the whole image minus mip 0's, dB.
    pub gain_db: f64,
    /// PSNR over the scene's mask minus mip 0's, dB.
    pub gain_mask_db: f64,
    /// Median frame time added to mip 0's, ms.
    pub added_ms: f64,
    /// Smallest and largest added time over the rounds, ms.
    pub added_spread_ms: (f64, f64),
    /// The bench's verdict on the added time.
    pub verdict: String,
}

/// A CSV text as rows of named columns: the header's names, then each row's cells.
struct Table {
    header: Vec<String>,
    rows: Vec<Vec<String>>,
}

impl Table {
    fn parse(text: &str, what: &str) -> Result<Table, String> {
        let mut lines = text.lines().filter(|line| !line.trim().is_empty());
        let header = lines
            .next()
            .ok_or_else(|| format!("{what}: empty"))?
            .split(',')
            .map(str::to_string)
            .collect();
        let rows = lines
            .map(|line| line.split(',').map(str::to_string).collect())
            .collect();
        Ok(Table { header, rows })
    }

    /// The index of column `name`, or the error that names the table and the column.
    fn column(&self, name: &str, what: &str) -> Result<usize, String> {
        self.header
            .iter()
            .position(|column| column == name)
            .ok_or_else(|| format!("{what}: no column '{name}'"))
    }
}

/// The cell of `row` in `column`; empty where the row is short.
fn cell(row: &[String], column: usize) -> &str {
    row.get(column).map_or("", String::as_str)
}

/// The cell of `row` in `column` as a number, or the error that names it.
fn number(row: &[String], column: usize, what: &str) -> Result<f64, String> {
    let cell = cell(row, column);
    cell.parse()
        .map_err(|_| format!("{what}: '{cell}' in column {} is not a number", column + 1))
}

/// Joins the quality lab's `table.csv` (`quality`) with `mode_costs --csv` (`costs`): one row per
/// scene and method (other than mip 0) found in both, on scenes with a mip-0 row, in the quality
/// table's order.
pub fn join(quality: &str, costs: &str) -> Result<Vec<CostQuality>, String> {
    let (q, c) = ("quality table", "mode_costs table");
    let quality = Table::parse(quality, q)?;
    let costs = Table::parse(costs, c)?;
    let [scene, method, psnr, psnr_mask] =
        ["scene", "method", "psnr_db", "psnr_mask_db"].map(|name| quality.column(name, q));
    let (scene, method, psnr, psnr_mask) = (scene?, method?, psnr?, psnr_mask?);
    let [cost_scene, mode, added, added_min, added_max, verdict] = [
        "scene",
        "mode",
        "added_ms",
        "added_min_ms",
        "added_max_ms",
        "verdict",
    ]
    .map(|name| costs.column(name, c));
    let (cost_scene, mode, added, added_min, added_max, verdict) =
        (cost_scene?, mode?, added?, added_min?, added_max?, verdict?);
    let mut joined = Vec::new();
    for row in &quality.rows {
        let (row_scene, row_method) = (cell(row, scene), cell(row, method));
        let Some(mip0) = quality
            .rows
            .iter()
            .find(|r| cell(r, scene) == row_scene && cell(r, method) == "mip0")
        else {
            continue;
        };
        let Some(cost) = costs
            .rows
            .iter()
            .find(|r| cell(r, cost_scene) == row_scene && cell(r, mode) == row_method)
        else {
            continue;
        };
        if row_method == "mip0" {
            continue;
        }
        joined.push(CostQuality {
            scene: row_scene.to_string(),
            method: row_method.to_string(),
            gain_db: number(row, psnr, q)? - number(mip0, psnr, q)?,
            gain_mask_db: number(row, psnr_mask, q)? - number(mip0, psnr_mask, q)?,
            added_ms: number(cost, added, c)?,
            added_spread_ms: (number(cost, added_min, c)?, number(cost, added_max, c)?),
            verdict: cell(cost, verdict).to_string(),
        });
    }
    Ok(joined)
}

/// The joined rows as a Markdown table.
pub fn markdown(rows: &[CostQuality]) -> String {
    let mut text = String::from(
        "| scene | method | PSNR gain over mip 0, dB | over the mask, dB | added ms (min to max) | verdict |\n\
         | --- | --- | ---: | ---: | ---: | --- |\n",
    );
    for row in rows {
        let _ = writeln!(
            text,
            "| {} | {} | {:+.2} | {:+.2} | {:+.3} ({:+.3} to {:+.3}) | {} |",
            row.scene,
            row.method,
            row.gain_db,
            row.gain_mask_db,
            row.added_ms,
            row.added_spread_ms.0,
            row.added_spread_ms.1,
            row.verdict
        );
    }
    text
}

/// Draws the joined rows to `path` (PNG): one panel per scene, the PSNR gain over the mask against
/// the added frame time, a bar from the smallest to the largest added time, the point hollow where
/// the bench found the time not separable from mip 0's.
pub fn plot(rows: &[CostQuality], path: &Path) -> Result<PathBuf, LabError> {
    let mut panels: Vec<ScatterPanel> = Vec::new();
    for row in rows {
        let point = ScatterPoint {
            x: row.added_ms,
            x_spread: Some(row.added_spread_ms),
            y: row.gain_mask_db,
            method: row.method.clone(),
            separable: row.verdict.starts_with("slower") || row.verdict.starts_with("faster"),
        };
        match panels.iter_mut().find(|panel| panel.title == row.scene) {
            Some(panel) => panel.points.push(point),
            None => panels.push(ScatterPanel {
                title: row.scene.clone(),
                points: vec![point],
            }),
        }
    }
    scatter_plot(
        path,
        &panels,
        ("ms added to mip 0", "PSNR gain over mip 0, mask, dB"),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    const QUALITY: &str = "scene,method,psnr_db,psnr_mask_db,ssim\n\
                           plane,mip0,20.0,15.0,0.5\n\
                           plane,cone,24.5,21.0,0.7\n\
                           plane,ray_diff,25.0,22.5,0.7\n\
                           torus,wireframe,30.0,28.0,0.9\n";
    const COSTS: &str =
        "scene,mode,median_ms,round_min_ms,round_max_ms,added_ms,added_min_ms,added_max_ms,verdict\n\
                         plane,mip0,8.0,7.9,8.1,0.0,-0.2,0.2,baseline\n\
                         plane,cone,8.2,8.15,8.3,0.2,0.05,0.4,slower\n\
                         torus,wireframe,9.0,8.9,9.1,0.5,0.3,0.7,slower\n";

    #[test]
    fn joins_the_gain_over_mip0_with_the_added_time() {
        let rows = join(QUALITY, COSTS).unwrap();
        // ray_diff has no time, the torus no mip-0 row: only the cone on the plane is left.
        assert_eq!(rows.len(), 1);
        let cone = &rows[0];
        assert_eq!((cone.scene.as_str(), cone.method.as_str()), ("plane", "cone"));
        assert!((cone.gain_db - 4.5).abs() < 1e-12 && (cone.gain_mask_db - 6.0).abs() < 1e-12);
        assert_eq!((cone.added_ms, cone.added_spread_ms), (0.2, (0.05, 0.4)));
        assert!(
            markdown(&rows).contains("| plane | cone | +4.50 | +6.00 | +0.200 (+0.050 to +0.400) | slower |")
        );
    }

    #[test]
    fn a_missing_column_is_named() {
        let error = join("scene,method\nplane,mip0\n", COSTS).unwrap_err();
        assert_eq!(error, "quality table: no column 'psnr_db'");
    }
}
