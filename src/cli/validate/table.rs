//! A table to validate as read from a file (any format of [`crate::tables`]:
//! CSV as numpy, pandas or a spreadsheet writes it, fricosc's or pandas' JSON,
//! JSON Lines; its columns as [`fricosc::validation::Table`] names them), and
//! the CSV of its comparison.

use crate::error::Result;
use crate::output::csv_records;
use crate::tables::{read_columns, Kind};
use fricosc::validation::{Column, OscillationValidation, Table, TransverseRow, Validation};

/// Most rows one file may hold.
pub const MAX_ROWS: usize = crate::grid::MAX_ROWS;

/// [`Table::COLUMNS`] with what each holds: `shape` text; `mu_ratio`, `mu`,
/// `transverse_ratio` values that may have diverged (a finding, not a parse error).
const TABLE_COLUMNS: [(&str, Kind); Table::COLUMNS.len()] = {
    let mut c = [("", Kind::Number); Table::COLUMNS.len()];
    let mut k = 0;
    while k < c.len() {
        let kind = if matches!(k, 3 | 4 | 10) { Kind::Value } else { Kind::Number };
        let kind = if k == 5 { Kind::Label } else { kind };
        c[k] = (Table::COLUMNS[k], kind);
        k += 1;
    }
    c
};

/// Read a table (any format of [`crate::tables`]) into the library's
/// [`Table`]; `source` names it in errors. Every row is read and checked
/// before anything is compared.
pub fn read_table(text: &str, source: &str) -> Result<Table> {
    let mut c = read_columns(text, source, &TABLE_COLUMNS, MAX_ROWS)?;
    let mut columns = vec![];
    for (k, &(name, _)) in TABLE_COLUMNS.iter().enumerate() {
        if let Some(v) = c.numbers[k].take() {
            columns.push((name, Column::Numbers(v)));
        } else if let Some(l) = c.labels[k].take() {
            columns.push((name, Column::Labels(l)));
        }
    }
    Ok(Table::from_columns(&c.names, columns, &c.format, source)?)
}

/// Every compared row of an oscillation table as CSV.
pub fn oscillation_csv(v: &OscillationValidation) -> Result<String> {
    let n = crate::output::num;
    let header = "row vhat amp tangential_amp phase mu_ratio exact error relative_error regime exact_error_estimate";
    let mut header: Vec<&str> = header.split(' ').collect();
    let plane = v.rows.iter().any(|r| r.transverse.is_some()); // the force across and its errors
    if plane {
        header.extend("transverse_amp transverse_phase transverse_ratio transverse_exact transverse_error".split(' '));
        header.extend(v.peer.map(|_| "transverse_peer_error"));
    }
    let rows = v.rows.iter().map(|r| {
        let mut cells = vec![
            r.row.to_string(),
            n(r.vhat),
            n(r.amp),
            n(r.tangential_amp),
            n(r.phase),
            n(r.mu_ratio),
            n(r.exact),
            n(r.error),
            r.relative_error.map(n).unwrap_or_default(),
            r.regime.clone(),
            n(r.exact_error_estimate),
        ];
        if let (true, t) = (plane, r.transverse.as_ref()) {
            let f = |g: fn(&TransverseRow) -> Option<f64>| t.and_then(g).map(n).unwrap_or_default();
            cells.extend([f(|t| Some(t.transverse_amp)), f(|t| Some(t.transverse_phase)), f(|t| t.transverse_ratio)]);
            cells.extend([f(|t| Some(t.transverse_exact)), f(|t| t.transverse_error)]);
            cells.extend(v.peer.map(|_| f(|t| t.transverse_peer_error)));
        }
        (cells, r.peer_error)
    });
    compared_csv(&header, v.peer.is_some(), rows)
}

/// CSV of compared rows: `header`, then each row's cells, with a
/// `peer_error` column where the comparison ran the peer.
fn compared_csv(header: &[&str], peer: bool, rows: impl Iterator<Item = (Vec<String>, Option<f64>)>) -> Result<String> {
    let mut head: Vec<String> = header.iter().map(|h| h.to_string()).collect();
    if peer {
        head.push("peer_error".into());
    }
    let mut records = vec![head];
    for (mut cells, p) in rows {
        if peer {
            cells.push(p.map(crate::output::num).unwrap_or_default());
        }
        records.push(cells);
    }
    Ok(csv_records(&records))
}

/// Every compared row as CSV (one header line); on a system each row's
/// period (empty: none, a mean) and the exact value's error estimate.
pub fn rows_csv(v: &Validation) -> Result<String> {
    let n = crate::output::num;
    // The velocity as the file gives it (`vhat` where its rows have it).
    let velocity = if v.rows.iter().any(|r| r.vhat.is_some()) { "vhat" } else { "vbar" };
    let mut header =
        vec!["row", velocity, "amp", "mu_ratio", "exact", "error", "relative_error", "regime", "jumping_share"];
    header.extend(v.system.iter().flat_map(|_| ["period", "exact_error_estimate"]));
    let rows = v.rows.iter().map(|r| {
        let mut cells = vec![
            r.row.to_string(),
            n(r.vhat.unwrap_or(r.vbar)),
            n(r.amp),
            n(r.mu_ratio),
            n(r.exact),
            n(r.error),
            r.relative_error.map(n).unwrap_or_default(),
            r.regime.name().into(),
            n(r.jumping_share),
        ];
        if v.system.is_some() {
            cells.extend([
                r.period.map(|k| k.to_string()).unwrap_or_default(),
                r.exact_error_estimate.map(n).unwrap_or_default(),
            ]);
        }
        (cells, r.peer_error)
    });
    compared_csv(&header, v.peer.is_some(), rows)
}
