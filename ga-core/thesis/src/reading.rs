//! One reading of the fixture, as printed or corrected: the one place that says which
//! definitions, `uses` and formulas an entry is checked with.

use crate::corrections::{
    lookup2, CORRECTED_FORMULAS, CORRECTED_LETS, CORRECTED_STEPS, CORRECTED_USES, CORRECTION_AS,
};
use crate::fixture::{Entry, Fixture};
use crate::scope::Scope;

/// Printed (`corrected = false`) or corrected reading of the fixture.
pub struct Ctx<'a> {
    /// The fixture.
    pub fx: &'a Fixture,
    /// Whether the corrections above apply.
    pub corrected: bool,
}

impl Ctx<'_> {
    fn uses(&self, e: &Entry) -> Vec<String> {
        let text = match (self.corrected, lookup2(CORRECTED_USES, &e.id)) {
            (true, Some(u)) => u,
            _ => e.field("uses").unwrap_or(""),
        };
        text.split(',')
            .map(|x| x.trim().to_string())
            .filter(|x| !x.is_empty())
            .collect()
    }
    fn add_lets(&self, e: &Entry, s: &mut Scope, seen: &mut Vec<String>) {
        if seen.contains(&e.id) {
            return;
        }
        seen.push(e.id.clone());
        for u in self.uses(e) {
            if let Some(d) = self.fx.entry(&u) {
                // `uses_corrected`: this entry is checked with the corrected definitions of `d`
                // (its own erratum is counted there, not here).
                let fixed = e
                    .field("uses_corrected")
                    .is_some_and(|c| c.split(',').any(|x| x.trim() == d.id));
                if fixed && !self.corrected {
                    let ctx = Ctx {
                        fx: self.fx,
                        corrected: true,
                    };
                    ctx.add_lets(d, s, seen);
                } else {
                    self.add_lets(d, s, seen);
                }
            }
        }
        for (n, x) in &e.lets {
            let fixed = CORRECTED_LETS
                .iter()
                .find(|(id, name, _)| self.corrected && *id == e.id && name == n)
                .map(|(_, _, v)| *v);
            s.define(n, fixed.unwrap_or(x));
        }
    }
    /// The scope of an entry (with corrected definitions when `corrected`).
    pub fn scope(&self, e: &Entry) -> Scope {
        let mut s = Scope::new();
        for (name, c) in &self.fx.points {
            s.point(name, [&c[0], &c[1], &c[2]]);
        }
        let mut seen = Vec::new();
        self.add_lets(e, &mut s, &mut seen);
        s
    }
    /// The formula of an entry (corrected when `corrected` and a correction exists).
    pub fn formula_of(&self, id: &str) -> String {
        let own = lookup2(CORRECTION_AS, id).unwrap_or(id);
        match (self.corrected, lookup2(CORRECTED_FORMULAS, own)) {
            (true, Some(f)) => f.to_string(),
            _ => self
                .fx
                .entry(id)
                .and_then(|e| e.field("formula"))
                .unwrap_or("0")
                .to_string(),
        }
    }
    /// The printed steps (`formula` lines) of an entry, corrected when `corrected`.
    pub fn steps(&self, e: &Entry) -> Vec<String> {
        e.fields
            .iter()
            .filter(|(k, _)| k == "formula")
            .enumerate()
            .map(|(k, (_, v))| {
                let fixed = CORRECTED_STEPS
                    .iter()
                    .find(|(id, step, _)| self.corrected && *id == e.id && *step == k + 1)
                    .map(|(_, _, t)| t.to_string());
                match (k, fixed) {
                    (_, Some(t)) => t,
                    (0, None) => self.formula_of(&e.id),
                    _ => v.clone(),
                }
            })
            .collect()
    }
    /// Whether anything about this entry (or what it uses) is corrected.
    pub(crate) fn has_correction(&self, e: &Entry) -> bool {
        let mut ids = vec![e.id.clone()];
        let mut i = 0;
        while i < ids.len() {
            if let Some(x) = self.fx.entry(&ids[i]) {
                for u in (Ctx {
                    fx: self.fx,
                    corrected: false,
                })
                .uses(x)
                {
                    if !ids.contains(&u) {
                        ids.push(u);
                    }
                }
            }
            i += 1;
        }
        e.field("erratum").is_some()
            || ids.iter().any(|id| {
                lookup2(CORRECTED_FORMULAS, id).is_some()
                    || CORRECTED_STEPS.iter().any(|(x, _, _)| x == id)
                    || lookup2(CORRECTED_USES, id).is_some()
                    || CORRECTED_LETS.iter().any(|(x, _, _)| x == id)
            })
            || e.field("kind") == Some("rule_line_line")
    }
    /// The corrections that concern the entry itself, as text.
    pub(crate) fn correction_text(&self, e: &Entry) -> String {
        let mut out = Vec::new();
        let own = lookup2(CORRECTION_AS, &e.id).unwrap_or(&e.id);
        if let Some(f) = lookup2(CORRECTED_FORMULAS, own) {
            out.push(format!("formula = `{f}`"));
        }
        for (id, step, t) in CORRECTED_STEPS {
            if *id == e.id {
                out.push(format!("step {step} = `{t}`"));
            }
        }
        for (id, n, v) in CORRECTED_LETS {
            if *id == e.id {
                out.push(format!("`{n} = {v}`"));
            }
        }
        if let Some(u) = lookup2(CORRECTED_USES, &e.id) {
            out.push(format!("the symbols of ({u})"));
        }
        if out.is_empty() {
            "the corrected formulas and definitions it depends on".into()
        } else {
            out.join("; ")
        }
    }
}
