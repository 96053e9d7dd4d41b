//! A model's declarative variable table: one [`Row`] per variable, in the order of the
//! modelDescription.xml. Everything the FMI layer asks of a variable follows from its row:
//! the XML declaration ([`Row::var`]), the get/set dispatch ([`Row::get`], [`Row::set`]),
//! the value check with its message ([`Rule`]) and the FMU state (every row with a setter
//! is stored, in [`Table::stored`] order). Adding a variable is adding one row.
//!
//! Integer mirrors ([`integer_mirrors`]): for masters without Enumeration support (libcosim,
//! Ecos skip those variables), each Enumeration row named in a model's list gets an Integer
//! twin generated from it: the same getter, setter and check (the same value: setting one sets
//! the other), its range and the codes in its description taken from the enumeration's items,
//! so a code added to an enumeration is a code of its mirror. A mirror is not stored in the
//! state (its enumeration is).

use fmi_layer::core::bytes::{ByteReader, ByteWriter};
use fmi_layer::core::model::{ModelError, ModelResult};
use fmi_layer::core::variables::{Causality, EnumType, Kind, Variable};
use std::sync::Arc;

/// Reads a variable's value from the model's values `S` (Integer and Boolean as f64); shared
/// by a row and its Integer mirror.
pub type Getter<S> = Arc<dyn Fn(&S) -> f64 + Send + Sync>;
/// Stores a value that passed the row's [`Rule`] into the model's values `S`.
pub type Setter<S> = Arc<dyn Fn(&mut S, f64) + Send + Sync>;
/// A plain getter and setter of one value of `S` (what most rows are built from).
pub type Access<S> = (fn(&S) -> f64, fn(&mut S, f64));

/// The check of a value when the host sets it (and when a state is restored). A value
/// that breaks it is refused with [`ModelError::InvalidValue`] naming the variable's
/// causality, name, value and unit; parameters without a rule are checked together at
/// exit of initialization by the model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rule {
    /// Any value (checked later, or not at all).
    Any,
    /// A finite number; the message's predicate (e.g. `is not a finite number`).
    Finite(&'static str),
    /// A finite number >= 0 (`is not a finite number >= 0`).
    NonNegative,
    /// A number in the half-open interval (lo, hi].
    OpenClosed(f64, f64),
    /// A number in the closed interval [lo, hi].
    Closed(f64, f64),
    /// A whole number that is one of the enumeration's codes.
    Code(&'static EnumType),
}

impl Rule {
    /// `None` if `x` passes; otherwise the message's predicate (`is …`), `unit` being the
    /// variable's unit.
    pub fn broken_by(self, x: f64, unit: &str) -> Option<String> {
        match self {
            Rule::Any => None,
            Rule::Finite(what) => (!x.is_finite()).then(|| what.to_string()),
            Rule::NonNegative => (!(x.is_finite() && x >= 0.0)).then(|| "is not a finite number >= 0".to_string()),
            Rule::OpenClosed(lo, hi) => {
                (!(x > lo && x <= hi)).then(|| format!("is out of range: it must be in ({lo}, {hi}] {unit}").trim_end().to_string())
            }
            Rule::Closed(lo, hi) => {
                (!(x >= lo && x <= hi)).then(|| format!("is out of range: it must be in [{lo}, {hi}] {unit}").trim_end().to_string())
            }
            Rule::Code(t) => {
                let ok = x.fract() == 0.0 && t.item(x as i64).is_some();
                (!ok).then(|| format!("is out of range: it must be {}", choices(t)))
            }
        }
    }
}

/// The codes of an enumeration as a message lists them: `0 (full), 1 (table) or 2 (auto)`.
pub fn choices(t: &EnumType) -> String {
    let items: Vec<String> = t.items.iter().map(|(name, code, _)| format!("{code} ({name})")).collect();
    match items.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
        _ => items.concat(),
    }
}

/// The codes of an enumeration as a description lists them: `0 = full, 1 = table, 2 = auto`.
pub fn codes(t: &EnumType) -> String {
    t.items.iter().map(|(name, code, _)| format!("{code} = {name}")).collect::<Vec<_>>().join(", ")
}

/// `rows` with the Integer mirror of each Enumeration row named in `mirrors` ((enumeration,
/// mirror name, value reference)) appended, in the list's order.
///
/// # Panics
/// If a name in `mirrors` is not an Enumeration row of `rows` (a programming error in a table,
/// found by every test that builds it).
pub fn integer_mirrors<S>(mut rows: Vec<Row<S>>, mirrors: &[(&str, &str, u32)]) -> Vec<Row<S>> {
    for &(of, name, vr) in mirrors {
        let row = rows.iter().find(|r| r.var.name == of).and_then(|r| r.integer_mirror(name, vr));
        rows.push(row.unwrap_or_else(|| panic!("{of} is an Enumeration row of the table")));
    }
    rows
}

/// The word a message puts before a variable's name: `input`, `parameter`, or nothing for
/// an output (only checked when a state is restored) or a local variable (a continuous
/// state, checked when the host sets it under Model Exchange).
pub fn role(c: Causality) -> &'static str {
    match c {
        Causality::Input => "input",
        Causality::Parameter => "parameter",
        Causality::Output | Causality::Local => "",
    }
}

/// One variable: its declaration, how it is read, stored and checked.
pub struct Row<S> {
    /// The declaration in modelDescription.xml (value reference, type, unit, start, range, text).
    pub var: Variable,
    /// Its current value.
    pub get: Getter<S>,
    /// Stores a value: every row with a setter is part of the FMU state; `None` for an
    /// output computed from the others.
    pub set: Option<Setter<S>>,
    /// The check when the host sets it or a state holds it.
    pub rule: Rule,
    /// Position in the serialized state, when the model's state order is not the table's
    /// (all stored rows of a table give one, or none does).
    pub slot: Option<usize>,
    /// For an Integer mirror, the name of the Enumeration it mirrors: not stored (the
    /// enumeration is), and a set reports the enumeration's declaration ([`Table::set`]).
    pub mirror_of: Option<String>,
}

impl<S> Row<S> {
    /// A row read by `get`, stored by `set`, checked by `rule`.
    pub fn new(var: Variable, get: impl Fn(&S) -> f64 + Send + Sync + 'static, set: impl Fn(&mut S, f64) + Send + Sync + 'static, rule: Rule) -> Self {
        Row { var, get: Arc::new(get), set: Some(Arc::new(set)), rule, slot: None, mirror_of: None }
    }

    /// An output computed by the model: read only, not stored.
    pub fn output(var: Variable, get: impl Fn(&S) -> f64 + Send + Sync + 'static) -> Self {
        Row { var, get: Arc::new(get), set: None, rule: Rule::Any, slot: None, mirror_of: None }
    }

    /// This row at position `slot` of the serialized state.
    pub fn at_slot(self, slot: usize) -> Self {
        Row { slot: Some(slot), ..self }
    }

    /// The Integer mirror of this Enumeration row: `name` at value reference `vr`, the same
    /// value (getter, setter, check), causality, variability, start and dependencies; its range
    /// the enumeration's smallest and largest code, its description the codes with their
    /// names and then the enumeration's own. `None` if this row is not an Enumeration.
    pub fn integer_mirror(&self, name: &str, vr: u32) -> Option<Row<S>> {
        let Kind::Enumeration(t) = self.var.kind else { return None };
        let mut v = self.var.clone();
        v.name = name.into();
        v.value_reference = vr;
        v.kind = Kind::Integer;
        v.min = t.items.iter().map(|i| i.1).min().map(|c| c as f64);
        v.max = t.items.iter().map(|i| i.1).max().map(|c| c as f64);
        v.description = format!("Integer mirror of the Enumeration {} for masters without Enumeration support (libcosim, Ecos): the same value, {}. {}",
            self.var.name, codes(t), self.var.description);
        // An enumeration's setter checks nothing beyond its rule (Any for some, checked at
        // exit of initialization): the mirror takes the codes' rule, so a wrong code is refused
        // when set.
        let rule = if self.set.is_some() { Rule::Code(t) } else { Rule::Any };
        Some(Row { var: v, get: self.get.clone(), set: self.set.clone(), rule, slot: None, mirror_of: Some(self.var.name.clone()) })
    }

    /// [`Rule::broken_by`] as the error the host sees.
    pub fn check(&self, x: f64) -> ModelResult<()> {
        let unit = self.var.unit.unwrap_or("");
        match self.rule.broken_by(x, unit) {
            None => Ok(()),
            Some(rule) => Err(ModelError::invalid(role(self.var.causality), self.var.name.clone(), x, unit, rule)),
        }
    }
}

/// A model's rows, in table order, with the state order derived from them.
pub struct Table<S> {
    rows: Vec<Row<S>>,
    stored: Vec<usize>,
}

impl<S> Table<S> {
    /// The table of `rows`. The stored rows (those with a setter) are serialized in slot
    /// order if they carry slots, else in table order.
    ///
    /// # Panics
    /// If only some stored rows carry a slot, or the slots are not 0, 1, …, n-1 (a
    /// programming error in a table, found by every test that builds it).
    pub fn new(rows: Vec<Row<S>>) -> Self {
        let mut stored: Vec<usize> = (0..rows.len()).filter(|&i| rows[i].set.is_some() && rows[i].mirror_of.is_none()).collect();
        if stored.iter().any(|&i| rows[i].slot.is_some()) {
            stored.sort_by_key(|&i| rows[i].slot.unwrap_or(usize::MAX));
            for (k, &i) in stored.iter().enumerate() {
                assert_eq!(rows[i].slot, Some(k), "state slot of {}", rows[i].var.name);
            }
        }
        Table { rows, stored }
    }

    /// Every row, in table order.
    pub fn rows(&self) -> &[Row<S>] {
        &self.rows
    }

    /// The declarations, in table order (for [`fmi_layer::core::variables::ModelInfo::variables`]).
    pub fn variables(&self) -> Vec<Variable> {
        self.rows.iter().map(|r| r.var.clone()).collect()
    }

    /// The table index of the variable `name`.
    pub fn index(&self, name: &str) -> Option<usize> {
        self.rows.iter().position(|r| r.var.name == name)
    }

    /// The table indices of the stored rows, in state order.
    pub fn stored(&self) -> &[usize] {
        &self.stored
    }

    /// The value of row `i`.
    pub fn get(&self, s: &S, i: usize) -> f64 {
        (self.rows[i].get)(s)
    }

    /// Check a value for row `i` ([`Row::check`]).
    pub fn check(&self, i: usize, x: f64) -> ModelResult<()> {
        self.rows[i].check(x)
    }

    /// Store a checked value in row `i` (the FMI layer never sets an output: a row without
    /// a setter ignores it); returns the row's declaration (the caller drops what a changed
    /// parameter invalidates), for an Integer mirror that of its enumeration.
    pub fn set(&self, s: &mut S, i: usize, x: f64) -> &Variable {
        let row = &self.rows[i];
        if let Some(set) = &row.set {
            set(s, x);
        }
        match row.mirror_of.as_deref().and_then(|of| self.index(of)) {
            Some(e) => &self.rows[e].var,
            None => &row.var,
        }
    }

    /// [`Table::check`], and for the `load` input the joint's asperity `capacity` once one
    /// is built ([`crate::inputs::check_capacity`]).
    pub fn check_input(&self, i: usize, x: f64, capacity: Option<f64>) -> ModelResult<()> {
        self.check(i, x)?;
        match capacity {
            Some(c) if self.rows[i].var.name == "load" => crate::capacity::check_capacity(x, c),
            _ => Ok(()),
        }
    }

    /// Append `model`'s state header (`version`, then the number of stored values) and
    /// every stored value of `s`, in state order.
    pub fn write(&self, version: u8, s: &S, w: &mut ByteWriter) {
        w.u8(version);
        w.u16(u16::try_from(self.stored.len()).expect("fewer than 65536 variables"));
        for &i in &self.stored {
            w.f64(self.get(s, i));
        }
    }

    /// Read what [`Table::write`] wrote into `s` (a start from which every stored value is
    /// replaced): the version must be `version`, the count this table's, every value pass
    /// its row's rule, a Boolean be 0 or 1 and an Integer or Enumeration a whole number.
    /// `model` names the model in the messages.
    pub fn read(&self, model: &str, version: u8, r: &mut ByteReader, s: &mut S) -> ModelResult<()> {
        let found = r.u8(&format!("{model} state version")).map_err(rejected)?;
        if found != version {
            return Err(ModelError::RejectedState(format!("{model} state version {found}; this FMU reads version {version}")));
        }
        let n = usize::from(r.u16("value count").map_err(rejected)?);
        if n != self.stored.len() {
            return Err(ModelError::RejectedState(format!(
                "{model} state holds {n} values; version {version} has {}",
                self.stored.len()
            )));
        }
        for &i in &self.stored {
            let row = &self.rows[i];
            let x = r.f64(&row.var.name).map_err(rejected)?;
            row.check(x)?;
            let whole = x.fract() == 0.0;
            match row.var.kind {
                Kind::Boolean if x != 0.0 && x != 1.0 => {
                    return Err(ModelError::RejectedState(format!("{} = {x} is not a Boolean", row.var.name)));
                }
                Kind::Integer | Kind::Enumeration(_) if !whole => {
                    return Err(ModelError::RejectedState(format!("an Integer parameter holds {x}")));
                }
                _ => {}
            }
            self.set(s, i, x);
        }
        Ok(())
    }
}

/// A byte-level failure of a state read ([`ByteReader`]) as a rejected state.
pub fn rejected(e: impl std::fmt::Display) -> ModelError {
    ModelError::RejectedState(e.to_string())
}

/// Test support: every stored row of a table takes a value of its own, keeps it through
/// get/set and through the state's bytes.
/// `stored` says which variables the state must hold.
#[cfg(test)]
pub(crate) fn assert_round_trip<S: Default>(table: &Table<S>, model: &str, version: u8, stored: fn(&Variable) -> bool) {
    let rows = table.rows();
    let mut order = table.stored().to_vec();
    order.sort_unstable();
    assert_eq!(order, (0..rows.len()).filter(|&i| rows[i].mirror_of.is_none() && stored(&rows[i].var)).collect::<Vec<_>>(), "the stored variables");
    let mut v = S::default();
    for (i, row) in rows.iter().enumerate() {
        assert_eq!(table.get(&v, i).to_bits(), row.var.start.unwrap_or(0.0).to_bits(), "start of {}", row.var.name);
    }
    for &i in table.stored() {
        let row = &rows[i];
        let x = match row.var.kind {
            Kind::Boolean | Kind::Integer | Kind::Enumeration(_) => 1.0,
            _ if row.var.name == "temperature" => 300.0,
            _ if let Rule::OpenClosed(lo, hi) = row.rule => lo + 0.625 * (hi - lo),
            _ => row.var.start.unwrap_or(0.0) * 1.25 + i as f64,
        };
        table.check(i, x).unwrap();
        table.set(&mut v, i, x);
        assert_eq!(table.get(&v, i), x, "{}", row.var.name);
    }
    let mut w = ByteWriter::default();
    table.write(version, &v, &mut w);
    assert_eq!(w.buf.len(), 1 + 2 + 8 * table.stored().len());
    let mut back = S::default();
    let mut r = ByteReader::new(&w.buf);
    table.read(model, version, &mut r, &mut back).unwrap();
    r.finish().unwrap();
    for &i in table.stored() {
        assert_eq!(table.get(&back, i).to_bits(), table.get(&v, i).to_bits(), "{}", rows[i].var.name);
    }
    let mut r = ByteReader::new(&w.buf);
    let e = table.read(model, version.wrapping_add(1), &mut r, &mut back).unwrap_err().to_string();
    assert_eq!(e, format!("{model} state version {version}; this FMU reads version {}", version.wrapping_add(1)));
}
