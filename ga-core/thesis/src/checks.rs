//! The checks, one per `kind` of fixture entry, dispatched by [`CHECKS`]: each recomputes an
//! entry with the generated products and judges the printed formula against it.
//!
//! An entry is checked as printed first; when that fails and a correction exists (see
//! `corrections`), it is checked again with the corrected reading, and the row records both.

use std::fmt::Write as _;

use ga_core::symbolic::Poly;

use crate::defs::check_defs;
use crate::fixture::{Entry, Fixture, FORMULAS};
use crate::meets::{check_meet, check_meet_def, check_square, meet_operands};
use crate::multivector::SymMultivector;
use crate::notation::Notation;
use crate::objects::{
    aux_mv, blade, computed_in, coords, int, line_aux, n_bar, n_inf, p, parse_in, plane_aux,
    point_at, point_of, pseudo, reduce_quadric, sc, thesis_dual, vec3, wedge_all,
};
use crate::products::{dual, gp, lc, rev, wedge};
use crate::reading::Ctx;
use crate::rules;
use crate::scope::Scope;
use crate::verdict::{corrected, invert, judge, judge_steps, rat_str, Row, Verdict};

/// One entry being checked in one reading: what a check reads, and what it writes besides
/// its verdict.
pub(crate) struct Job<'a> {
    /// The reading (printed or corrected).
    pub(crate) ctx: &'a Ctx<'a>,
    /// The entry.
    pub(crate) entry: &'a Entry,
    /// The entry's scope in this reading.
    pub(crate) scope: Scope,
    /// The entry's `kind`.
    pub(crate) kind: String,
    /// The first printed step (corrected in the corrected reading).
    pub(crate) formula: String,
    /// What was compared with what.
    pub(crate) method: String,
    /// Markdown details.
    pub(crate) detail: String,
}

impl Job<'_> {
    /// The first printed step, read in the entry's scope and expanded into point coordinates.
    fn printed(&self) -> SymMultivector {
        self.scope
            .expand(&parse_in(&self.scope, &self.formula))
            .expect("definitions expand")
    }
}

/// A check: the verdict of one entry (writing its method and details into the [`Job`]).
type Check = fn(&mut Job) -> Verdict;

/// The check of each `kind`, first match wins; a pattern ending in `*` matches every kind with
/// that prefix.
const CHECKS: &[(&str, Check)] = &[
    ("notation", notation),
    ("dual", dual_sign),
    ("metric", metric),
    ("meet_def_*", |j| {
        check_meet_def(j.ctx, j.entry, &j.kind, &mut j.method, &mut j.detail)
    }),
    ("rule_line_line_full", |j| {
        rules::line_line_full(&mut j.method, &mut j.detail)
    }),
    ("reflect_vec", reflect_vec),
    ("identity", identity),
    ("point", point),
    ("example_point", example_point),
    ("point_dot_nbar", point_dot_nbar),
    ("point_dot_point", point_dot_point),
    ("point_wedge_point", point_wedge_point),
    ("line", line),
    ("example_line", example_line),
    ("example_line_point", example_line_point),
    ("plane", plane),
    ("sphere", sphere),
    ("translate_x", translate),
    ("translate_n", translate),
    ("translate_nbar", translate),
    ("translate_point", translate),
    ("rotate_e3e1", rotate),
    ("rotate_e3e2", rotate),
    ("rotate_e1e2", rotate),
    ("dilation", dilation),
    ("reflection", reflection),
    ("reflect_pl", reflect),
    ("reflect_plp", reflect),
    ("meet_line_line_terms", meet_line_line_terms),
    ("meet_*", |j| {
        check_meet(&j.formula, &j.scope, &j.kind, &mut j.method, &mut j.detail)
    }),
    ("defs_*", |j| {
        check_defs(
            j.ctx.fx,
            j.entry,
            &j.scope,
            &j.kind,
            &mut j.method,
            &mut j.detail,
        )
    }),
    ("square_*", |j| {
        check_square(&j.formula, &j.scope, &j.kind, &mut j.method, &mut j.detail)
    }),
    ("rule_*", |j| {
        rules::check_rule(
            j.ctx,
            j.entry,
            &j.scope,
            &j.kind,
            &mut j.method,
            &mut j.detail,
        )
    }),
];

/// The check of a kind, if any.
fn check_of(kind: &str) -> Option<Check> {
    CHECKS
        .iter()
        .find(|(pattern, _)| match pattern.strip_suffix('*') {
            Some(prefix) => kind.starts_with(prefix),
            None => kind == *pattern,
        })
        .map(|(_, check)| *check)
}

/// Runs every check of the fixture, in fixture order.
pub fn run() -> Vec<Row> {
    let fx = Fixture::parse(FORMULAS).expect("fixture parses");
    fx.entries.iter().map(|e| check(&fx, e)).collect()
}

fn check(fx: &Fixture, e: &Entry) -> Row {
    let printed_ctx = Ctx {
        fx,
        corrected: false,
    };
    let (method, verdict, mut detail) = evaluate(&printed_ctx, e);
    let mut correction = None;
    if matches!(verdict, Verdict::Differs | Verdict::RuleFails) && printed_ctx.has_correction(e) {
        let ctx = Ctx {
            fx,
            corrected: true,
        };
        let (_, v2, d2) = evaluate(&ctx, e);
        let text = ctx.correction_text(e);
        let _ = writeln!(
            detail,
            "\n**Correction:** {text}. Checked the same way: **{}**.\n",
            v2.label()
        );
        if matches!(v2, Verdict::RuleHolds | Verdict::RuleFails) && !d2.trim().is_empty() {
            let _ = writeln!(detail, "With the correction:\n\n{}", d2.trim_end());
        }
        correction = Some((text, v2));
    }
    // A rule whose corrected check changes the rule itself (not only the formulas it uses)
    // stays wrong.
    let rule_changed = matches!(
        e.field("kind"),
        Some("rule_line_line") | Some("rule_line_plane") | Some("rule_sphere_sphere")
    );
    let verdict = match (&verdict, &correction) {
        (Verdict::RuleFails, Some((_, Verdict::RuleHolds))) if !rule_changed => {
            Verdict::RuleHoldsCorrected
        }
        _ => verdict,
    };
    Row {
        id: e.id.clone(),
        title: e.title.clone(),
        source: e.field("source").unwrap_or("").to_string(),
        method,
        verdict,
        detail,
        correction,
        errata: e
            .field("erratum")
            .map(|k| k.split(',').map(|x| x.trim().to_string()).collect())
            .unwrap_or_default(),
    }
}

/// Checks one entry in one reading: `(method, verdict, details)`.
fn evaluate(ctx: &Ctx, e: &Entry) -> (String, Verdict, String) {
    let kind = e.field("kind").unwrap_or("").to_string();
    let formula = ctx
        .steps(e)
        .into_iter()
        .next()
        .unwrap_or_else(|| ctx.formula_of(&e.id));
    let mut job = Job {
        ctx,
        entry: e,
        scope: ctx.scope(e),
        kind,
        formula,
        method: String::new(),
        detail: String::new(),
    };
    let verdict = match check_of(&job.kind) {
        Some(check) => check(&mut job),
        None => {
            job.detail = format!("unknown kind `{}`", job.kind);
            Verdict::Differs
        }
    };
    (job.method, verdict, job.detail)
}

// ---------------------------------------------------------------------------------------------
// The checks of single kinds.

fn notation(j: &mut Job) -> Verdict {
    j.method = "nothing to compute: it fixes notation or defines a quantity".into();
    Verdict::Notation
}

fn dual_sign(j: &mut Job) -> Verdict {
    j.method = "I A (generated geometric product) against our dual A I⁻¹ (generated), \
              for A a general multivector with 32 symbolic coefficients"
        .into();
    let a = SymMultivector::from_coefficients(
        &(0..32)
            .map(|k| Poly::var(&format!("g{k}")))
            .collect::<Vec<_>>(),
    );
    let ia = gp(&pseudo(), &a);
    if ia == dual(&a).neg() {
        let _ = writeln!(
            j.detail,
            "I A = −dual(A) for every A: the thesis's dual is the negative of ours \
             (I is central and I² = −1, so A I⁻¹ = −I A)."
        );
        Verdict::Confirmed
    } else {
        let _ = writeln!(j.detail, "I A is not ±dual(A).");
        Verdict::Differs
    }
}

fn metric(j: &mut Job) -> Verdict {
    j.method = "the products e_i e_j of the basis vectors (generated geometric product)".into();
    let names = ["e1", "e2", "e3", "e", "ē"];
    let mut ok = true;
    for i in 0..5u8 {
        let sq = gp(&blade(1 << i), &blade(1 << i));
        let want = if i == 4 { int(-1) } else { int(1) };
        ok &= sq == want;
        for j in 0..5u8 {
            if i != j {
                let (a, b) = (blade(1 << i), blade(1 << j));
                ok &= gp(&a, &b) == gp(&b, &a).neg();
            }
        }
    }
    let _ = writeln!(
        j.detail,
        "{} square to 1, ē to −1, and every pair of distinct basis vectors anticommutes.",
        names[..4].join(", ")
    );
    if ok {
        Verdict::Confirmed
    } else {
        Verdict::Differs
    }
}

fn reflect_vec(j: &mut Job) -> Verdict {
    let (pl, ln) = (aux_mv(&plane_aux("omega")), aux_mv(&line_aux("beta")));
    let full = gp(&gp(&pl, &ln), &pl);
    // e_i eē of the thesis = our e_i45 (the sign of thesis_name is +1 for these).
    let v = [(25u8, 1u8), (26, 2), (28, 4)]
        .iter()
        .fold(SymMultivector::zero(), |acc, &(from, to)| {
            acc.add(&SymMultivector::blade(to, full.get(from)))
        });
    j.method = "the e1eē, e2eē, e3eē coefficients of P L P (generated products, aux forms) \
              read as a vector of R³"
        .into();
    let printed = parse_in(&j.scope, &j.formula);
    let verdict = judge(&printed, &v, &mut j.detail);
    let n = [p("omega3"), p("omega4"), p("omega2")];
    let d = [-p("beta4"), -p("beta5"), -p("beta6")];
    let dot = |a: &[Poly; 3], b: &[Poly; 3]| -> Poly { (0..3).map(|i| &a[i] * &b[i]).sum() };
    let (nd, nn) = (dot(&n, &d), dot(&n, &n));
    let mirror = vec3([0, 1, 2].map(|i| &(&nn * &d[i]) - &(&(&nd * &n[i]) * &Poly::from(2))));
    let _ = writeln!(
        j.detail,
        "The vector is {} × (|n|² d − 2 (n·d) n), the mirror image of the direction \
         d = x2 − x1 of the line in the plane with normal n = (ω3, ω4, ω2), scaled by |n|² \
         (a positive factor): the reflected direction, as the text says.",
        v.ratio_to(&mirror)
            .map(|k| rat_str(&k))
            .unwrap_or_else(|| "not a multiple of".into())
    );
    verdict
}

fn identity(j: &mut Job) -> Verdict {
    let text = j.entry.field("computed").unwrap_or("0");
    let circle = j.entry.field("reduce") == Some("co si");
    let fix = |m: SymMultivector| {
        if circle {
            reduce_quadric(&m, "co", "si", -1)
        } else {
            m
        }
    };
    let computed = fix(j
        .scope
        .expand(&computed_in(&j.scope, text))
        .expect("expands"));
    j.method = format!(
        "`{text}` computed with the generated products{}",
        if circle {
            ", both sides reduced modulo co² + si² = 1"
        } else {
            ""
        }
    );
    let steps: Vec<SymMultivector> = j
        .ctx
        .steps(j.entry)
        .iter()
        .map(|t| fix(j.scope.expand(&parse_in(&j.scope, t)).expect("expands")))
        .collect();
    judge_steps(&steps, &computed, &mut j.detail)
}

fn point(j: &mut Job) -> Verdict {
    j.method = "2·up(x) from our conventions (x + ½|x|² n_inf + n_0, doubled)".into();
    judge(&j.printed(), &point_of("a"), &mut j.detail)
}

fn example_point(j: &mut Job) -> Verdict {
    j.method = "2·up((1,0,2))".into();
    judge(&j.printed(), &point_at([1, 0, 2]), &mut j.detail)
}

fn point_dot_nbar(j: &mut Job) -> Verdict {
    j.method = "X ⌋ n̄ with X = 2·up(x)".into();
    judge(&j.printed(), &lc(&point_of("a"), &n_bar()), &mut j.detail)
}

fn point_dot_point(j: &mut Job) -> Verdict {
    j.method = "X ⌋ Y with X = 2·up(x), Y = 2·up(y)".into();
    judge(
        &j.printed(),
        &lc(&point_of("a"), &point_of("b")),
        &mut j.detail,
    )
}

fn point_wedge_point(j: &mut Job) -> Verdict {
    j.method = "X ∧ Y".into();
    judge(
        &j.printed(),
        &wedge(&point_of("a"), &point_of("b")),
        &mut j.detail,
    )
}

fn line(j: &mut Job) -> Verdict {
    j.method = "P1 ∧ P2 ∧ n_inf".into();
    let c = wedge_all(&[point_of("a"), point_of("b"), n_inf()]);
    let v = judge(&j.printed(), &c, &mut j.detail);
    if v == Verdict::Differs {
        corrected(&mut j.detail, &c);
    }
    v
}

fn example_line(j: &mut Job) -> Verdict {
    j.method = "P(1,1,0) ∧ P(1,0,0) ∧ n_inf".into();
    let c = wedge_all(&[point_at([1, 1, 0]), point_at([1, 0, 0]), n_inf()]);
    judge(&j.printed(), &c, &mut j.detail)
}

fn example_line_point(j: &mut Job) -> Verdict {
    j.method = "(P(1,1,0) ∧ P(1,0,0) ∧ n_inf) ∧ P(0,2,0); and ∧ P(1,−1,0) for (II.19)".into();
    let l = wedge_all(&[point_at([1, 1, 0]), point_at([1, 0, 0]), n_inf()]);
    let on = wedge(&l, &point_at([1, -1, 0]));
    let _ = writeln!(
        j.detail,
        "(II.19) L ∧ P(1,−1,0) = `{}` (the point is on the line).",
        on.to_notation(Notation::Thesis)
    );
    let c = wedge(&l, &point_at([0, 2, 0]));
    let v = judge(&j.printed(), &c, &mut j.detail);
    if v == Verdict::Differs {
        corrected(&mut j.detail, &c);
    }
    v
}

fn plane(j: &mut Job) -> Verdict {
    j.method = "P1 ∧ P2 ∧ P3 ∧ n_inf".into();
    let c = wedge_all(&[point_of("a"), point_of("b"), point_of("c"), n_inf()]);
    let v = judge(&j.printed(), &c, &mut j.detail);
    if v == Verdict::Differs {
        corrected(&mut j.detail, &c);
    }
    v
}

fn sphere(j: &mut Job) -> Verdict {
    j.method = "P1 ∧ P2 ∧ P3 ∧ P4".into();
    let c = wedge_all(&[point_of("a"), point_of("b"), point_of("c"), point_of("d")]);
    judge(&j.printed(), &c, &mut j.detail)
}

fn translate(j: &mut Job) -> Verdict {
    let a = vec3(coords("t"));
    let half = sc(Poly::ratio(1, 2).expect("nonzero"));
    let t = int(1).add(&gp(&gp(&half, &n_inf()), &a));
    let obj = match j.kind.as_str() {
        "translate_x" => vec3(coords("a")),
        "translate_n" => n_inf(),
        "translate_nbar" => n_bar(),
        _ => point_of("a"),
    };
    j.method = "T_a X T̃_a with T_a = 1 + n_inf a / 2 (generated geometric products)".into();
    let c = gp(&gp(&t, &obj), &rev(&t));
    let v = judge(&j.printed(), &c, &mut j.detail);
    if v == Verdict::Differs {
        corrected(&mut j.detail, &c);
    }
    v
}

fn rotate(j: &mut Job) -> Verdict {
    let b = match j.kind.as_str() {
        "rotate_e3e1" => parse_in(&j.scope, "e3e1"),
        "rotate_e3e2" => parse_in(&j.scope, "e3e2"),
        _ => parse_in(&j.scope, "e1e2"),
    };
    let r = sc(p("co")).sub(&gp(&b, &sc(p("si"))));
    let xr = gp(&gp(&r, &point_of("a")), &rev(&r));
    let xp = j.printed();
    let printed_point = xp
        .scale(&Poly::from(2))
        .add(&n_inf().scale(&gp(&xp, &xp).get(0)))
        .sub(&n_bar());
    j.method = "R F(x) R̃ with R = co − B si, against F(x′) of the printed x′, both reduced \
              modulo co² + si² = 1"
        .into();
    let c = reduce_quadric(&xr, "co", "si", -1);
    let v = judge(
        &reduce_quadric(&printed_point, "co", "si", -1),
        &c,
        &mut j.detail,
    );
    if v == Verdict::Differs {
        let half = Poly::ratio(1, 2).expect("nonzero");
        let xprime = c.grade(1).map(|q| q * &half);
        let xprime = SymMultivector::blade(1, xprime.get(1))
            .add(&SymMultivector::blade(2, xprime.get(2)))
            .add(&SymMultivector::blade(4, xprime.get(4)));
        let _ = writeln!(
            j.detail,
            "\nCorrected x′ (computed, reduced):\n\n```text\n{}\n```",
            xprime.to_notation(Notation::Thesis)
        );
    }
    v
}

fn dilation(j: &mut Job) -> Verdict {
    let n = parse_in(&j.scope, "eē");
    let d = sc(p("ch")).add(&n.scale(&p("sh")));
    let e_minus = p("(ch - sh)^2");
    let c = gp(&gp(&d, &point_of("a")), &rev(&d)).scale(&e_minus);
    j.method = "e^−α D F(x) D̃ with D = ch + sh eē, e^−α = (ch − sh)², reduced modulo \
              ch² − sh² = 1"
        .into();
    let c = reduce_quadric(&c, "ch", "sh", 1);
    let pr = reduce_quadric(&j.printed(), "ch", "sh", 1);
    let v = judge(&pr, &c, &mut j.detail);
    if v == Verdict::Differs {
        // The same statement with α ↦ −α: F(e^α x) = e^α D F(x) D̃.
        let e_plus = p("(ch + sh)^2");
        let alt = parse_in(&j.scope, "2 (ch + sh)^2 x + (ch + sh)^4 x^2 n - nbar");
        let c2 = reduce_quadric(
            &gp(&gp(&d, &point_of("a")), &rev(&d)).scale(&e_plus),
            "ch",
            "sh",
            1,
        );
        let ok = reduce_quadric(&alt, "ch", "sh", 1) == c2;
        let _ = writeln!(
            j.detail,
            "\nWith the sign of α reversed, F(e^α x) = e^α D_α F(x) D̃_α: {}.",
            if ok {
                "holds exactly"
            } else {
                "does not hold either"
            }
        );
        let dn = gp(&gp(&d, &point_of("a")), &rev(&d));
        let _ = writeln!(
            j.detail,
            "\nComputed D_α F(x) D̃_α (reduced):\n\n```text\n{}\n```",
            reduce_quadric(&dn, "ch", "sh", 1).to_notation(Notation::Thesis)
        );
    }
    v
}

fn reflection(j: &mut Job) -> Verdict {
    let pi = wedge_all(&[
        point_at([1, 0, 0]),
        point_at([0, 1, 0]),
        point_at([0, 0, 1]),
        n_inf(),
    ]);
    let c = gp(&gp(&pi, &point_of("a")), &pi);
    j.method = "π X π with π = P(1,0,0) ∧ P(0,1,0) ∧ P(0,0,1) ∧ n_inf".into();
    let v = judge(&j.printed(), &c, &mut j.detail);
    if let Verdict::Scaled(k) = &v {
        let _ = writeln!(
            j.detail,
            "π X π = ({}) · F(x′): the reflection holds up to the scalar factor \
             (a multiple of π²), as expected of a homogeneous representation.",
            invert(k)
        );
    }
    v
}

fn meet_line_line_terms(j: &mut Job) -> Verdict {
    let (a, c, label) = meet_operands("meet_line_line");
    let ig = gp(&thesis_dual(&aux_mv(&a)), &aux_mv(&c));
    let target = ig.sub(&ig.grade(5));
    j.method = format!(
        "{label} term by term against ⟨(I A) C⟩₁ + ⟨(I A) C⟩₃, the geometric product \
         without its grade-5 part (what (A.48) simplifies it to), aux forms, generated products"
    );
    let v = judge(&parse_in(&j.scope, &j.formula), &target, &mut j.detail);
    if v == Verdict::Differs {
        corrected(&mut j.detail, &target);
    }
    v
}

/// `reflect_pl`, `reflect_plp`.
fn reflect(j: &mut Job) -> Verdict {
    check_reflect(&j.formula, &j.scope, &j.kind, &mut j.method, &mut j.detail)
}

/// Reflection of a line in a plane (A.103, A.105), in the aux forms of both.
fn check_reflect(
    formula: &str,
    scope: &Scope,
    kind: &str,
    method: &mut String,
    detail: &mut String,
) -> Verdict {
    let (pl, ln) = (aux_mv(&plane_aux("omega")), aux_mv(&line_aux("beta")));
    let pl_ln = gp(&pl, &ln);
    let printed = parse_in(scope, formula);
    let computed = if kind == "reflect_pl" {
        *method = "P L (geometric product) of the aux forms of the plane and the line".into();
        pl_ln
    } else {
        *method = "the e1eē, e2eē, e3eē part of P L P (geometric products) of the aux forms".into();
        let full = gp(&pl_ln, &pl);
        let part = [25u8, 26, 28]
            .iter()
            .fold(SymMultivector::zero(), |acc, &m| {
                acc.add(&SymMultivector::blade(m, full.get(m)))
            });
        // Geometric sanity: the direction part is the Euclidean mirror image of the direction.
        let n = [p("omega3"), p("omega4"), p("omega2")];
        let d = [-p("beta4"), -p("beta5"), -p("beta6")];
        let dot = |a: &[Poly; 3], b: &[Poly; 3]| -> Poly { (0..3).map(|i| &a[i] * &b[i]).sum() };
        let (nd, nn) = (dot(&n, &d), dot(&n, &n));
        let mirror = SymMultivector::from_coefficients(&[])
            .add(&SymMultivector::blade(
                25,
                &(&nn * &d[0]) - &(&(&nd * &n[0]) * &Poly::from(2)),
            ))
            .add(&SymMultivector::blade(
                26,
                &(&nn * &d[1]) - &(&(&nd * &n[1]) * &Poly::from(2)),
            ))
            .add(&SymMultivector::blade(
                28,
                &(&nn * &d[2]) - &(&(&nd * &n[2]) * &Poly::from(2)),
            ));
        let _ = writeln!(
            detail,
            "Computed: the direction part of P L P is {} × (|n|² d − 2 (n·d) n) in the blades \
             e1eē, e2eē, e3eē: the mirror image of the line's direction d = x2 − x1 in the plane \
             with normal n = (ω3, ω4, ω2).\n",
            part.ratio_to(&mirror)
                .map(|k| rat_str(&k))
                .unwrap_or_else(|| "not a multiple of".into())
        );
        part
    };
    let v = judge(&printed, &computed, detail);
    if v == Verdict::Differs {
        corrected(detail, &computed);
    }
    v
}
