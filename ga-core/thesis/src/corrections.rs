//! The errata of the thesis and their corrections: hand-written from the computed output, then
//! verified by the same computation (an erratum must fail as printed and pass as corrected).

/// Corrected closed forms, by equation.
pub const CORRECTED_FORMULAS: &[(&str, &str)] = &[
    (
        "A.14",
        "4((a1*b2 - a2*b1) e1e2e + (a1*b2 - a2*b1) e1e2ē + (a2*b3 - a3*b2) e2e3e + (a2*b3 - a3*b2) e2e3ē \
         + (a3*b1 - a1*b3) e3e1e + (a3*b1 - a1*b3) e3e1ē - (a1 - b1) e1eē - (a2 - b2) e2eē - (a3 - b3) e3eē)",
    ),
    (
        "II.25",
        "8(x1∧x2∧x3∧n) + 4((x1∧x2∧n∧nbar) - (x1∧x3∧n∧nbar) + (x2∧x3∧n∧nbar))",
    ),
    (
        "A.95",
        "(a1 co^2 - a1 si^2 + 2 a3 si co) e1 + a2 e2 + (a3 co^2 - a3 si^2 - 2 a1 si co) e3",
    ),
    (
        "A.96",
        "a1 e1 + (a2 co^2 - a2 si^2 + 2 a3 si co) e2 + (a3 co^2 - a3 si^2 - 2 a2 si co) e3",
    ),
    (
        "A.97",
        "(a1 co^2 - a1 si^2 - 2 a2 si co) e1 + (a2 co^2 - a2 si^2 + 2 a1 si co) e2 + a3 e3",
    ),
    (
        "II.53",
        "(alpha1*beta6 + alpha2*beta4 + alpha3*beta5 + alpha4*beta2 + alpha5*beta3 + alpha6*beta1) e \
         + (alpha1*beta6 + alpha2*beta4 + alpha3*beta5 + alpha4*beta2 + alpha5*beta3 + alpha6*beta1) ē",
    ),
    (
        "II.56",
        "(omega2*beta3 + omega1*beta4 - omega4*beta1) e1e + (omega2*beta3 + omega1*beta4 - omega4*beta1) e1ē \
         + (omega3*beta1 - omega2*beta2 + omega1*beta5) e2e + (omega3*beta1 - omega2*beta2 + omega1*beta5) e2ē \
         + (-omega3*beta3 + omega4*beta2 + omega1*beta6) e3e + (-omega3*beta3 + omega4*beta2 + omega1*beta6) e3ē \
         + (-omega3*beta4 - omega4*beta5 - omega2*beta6) eē",
    ),
    (
        "II.64",
        "-(mu3*beta3 + mu1*beta4 - mu5*beta1)^2 + (mu2*beta4 + mu3*beta3 - mu5*beta1)^2 \
         - (mu4*beta1 + mu1*beta5 - mu3*beta2)^2 + (mu4*beta1 + mu2*beta5 - mu3*beta2)^2 \
         - (mu5*beta2 + mu1*beta6 - mu4*beta3)^2 + (mu5*beta2 + mu2*beta6 - mu4*beta3)^2 \
         - (mu2*beta1 - mu1*beta1)^2 - (mu2*beta2 - mu1*beta2)^2 - (mu2*beta3 - mu1*beta3)^2 \
         + (mu4*beta4 + mu5*beta5 + mu3*beta6)^2",
    ),
];

/// Corrected steps `(equation, step (1-based), text)` of multi-step entries.
pub const CORRECTED_STEPS: &[(&str, usize, &str)] = &[
    (
        "II.51p",
        1,
        "2 x2 + x2^2 n - nbar",
    ),
    (
        "A.4",
        1,
        "( 2 x1 + x1^2 n - nbar ) ∧ ( 2 x2 + x2^2 n - nbar )",
    ),
    (
        "A.4",
        2,
        "4 ( x1 ∧ x2 ) + 2 x2^2 ( x1 ∧ n ) - 2 ( x1 ∧ nbar ) + 2 x1^2 ( n ∧ x2 ) + x1^2 x2^2 ( n ∧ n ) - x1^2 ( n ∧ nbar ) - 2 ( nbar ∧ x2 ) - x2^2 ( nbar ∧ n ) + ( nbar ∧ nbar )",
    ),
    (
        "A.20",
        1,
        "8 ( x1 ∧ x2 ∧ x3 ) + 4 x3^2 ( x1 ∧ x2 ∧ n ) - 4 ( x1 ∧ x2 ∧ nbar ) + 4 x2^2 ( x1 ∧ n ∧ x3 ) + 2 x2^2 x3^2 ( x1 ∧ n ∧ n ) - 2 x2^2 ( x1 ∧ n ∧ nbar ) - 4 ( x1 ∧ nbar ∧ x3 ) - 2 x3^2 ( x1 ∧ nbar ∧ n ) + 2 ( x1 ∧ nbar ∧ nbar ) - 4 x1^2 ( x2 ∧ n ∧ x3 ) - 2 x1^2 x3^2 ( x2 ∧ n ∧ n ) + 2 x1^2 ( x2 ∧ n ∧ nbar ) - 2 x1^2 ( n ∧ nbar ∧ x3 ) - x1^2 x3^2 ( n ∧ nbar ∧ n ) + x1^2 ( n ∧ nbar ∧ nbar ) + 4 ( x2 ∧ nbar ∧ x3 ) + 2 x3^2 ( x2 ∧ nbar ∧ n ) - 2 ( x2 ∧ nbar ∧ nbar ) + 2 x2^2 ( n ∧ nbar ∧ x3 ) + x2^2 x3^2 ( n ∧ nbar ∧ n ) - x2^2 ( n ∧ nbar ∧ nbar )",
    ),
    (
        "A.21",
        1,
        "8 ( x1 ∧ x2 ∧ x3 ) + 4 x3^2 ( x1 ∧ x2 ∧ n ) - 4 ( x1 ∧ x2 ∧ nbar ) + 4 x2^2 ( x1 ∧ n ∧ x3 ) - 2 x2^2 ( x1 ∧ n ∧ nbar ) - 4 ( x1 ∧ nbar ∧ x3 ) - 2 x3^2 ( x1 ∧ nbar ∧ n ) - 4 x1^2 ( x2 ∧ n ∧ x3 ) + 2 x1^2 ( x2 ∧ n ∧ nbar ) - 2 x1^2 ( n ∧ nbar ∧ x3 ) + x1^2 ( n ∧ nbar ∧ nbar ) + 4 ( x2 ∧ nbar ∧ x3 ) + 2 x3^2 ( x2 ∧ nbar ∧ n ) + 2 x2^2 ( n ∧ nbar ∧ x3 )",
    ),
    (
        "A.35",
        1,
        "16 ( x1 ∧ x2 ∧ x3 ∧ x4 ) + 8 x3^2 ( x1 ∧ x2 ∧ n ∧ x4 ) - 8 ( x1 ∧ x2 ∧ nbar ∧ x4 ) + 8 x1^2 ( x2 ∧ x3 ∧ n ∧ x4 ) - 8 ( x2 ∧ x3 ∧ nbar ∧ x4 ) + 8 x2^2 ( x3 ∧ x1 ∧ n ∧ x4 ) - 8 ( x3 ∧ x1 ∧ nbar ∧ x4 ) + ( 4 x3^2 - 4 x2^2 ) ( x1 ∧ n ∧ nbar ∧ x4 ) + ( 4 x1^2 - 4 x3^2 ) ( x2 ∧ n ∧ nbar ∧ x4 ) + ( 4 x2^2 - 4 x1^2 ) ( x3 ∧ n ∧ nbar ∧ x4 ) + 8 x4^2 ( x1 ∧ x2 ∧ x3 ∧ n ) - 4 x4^2 ( x1 ∧ x2 ∧ nbar ∧ n ) - 4 x4^2 ( x2 ∧ x3 ∧ nbar ∧ n ) - 4 x4^2 ( x3 ∧ x1 ∧ nbar ∧ n ) - 8 ( x1 ∧ x2 ∧ x3 ∧ nbar ) - 4 x3^2 ( x1 ∧ x2 ∧ n ∧ nbar ) - 4 x1^2 ( x2 ∧ x3 ∧ n ∧ nbar ) - 4 x2^2 ( x3 ∧ x1 ∧ n ∧ nbar )",
    ),
    (
        "A.36u",
        1,
        "alpha124 ( 1 - x3^2 ) ( e1 ∧ e2 ∧ e3 ∧ e ) - alpha124 ( 1 + x3^2 ) ( e1 ∧ e2 ∧ e3 ∧ ē ) + alpha234 ( 1 - x1^2 ) ( e1 ∧ e2 ∧ e3 ∧ e ) - alpha234 ( 1 + x1^2 ) ( e1 ∧ e2 ∧ e3 ∧ ē ) + alpha314 ( 1 - x2^2 ) ( e1 ∧ e2 ∧ e3 ∧ e ) - alpha314 ( 1 + x2^2 ) ( e1 ∧ e2 ∧ e3 ∧ ē ) + alpha123 ( x4^2 - 1 ) ( e1 ∧ e2 ∧ e3 ∧ e ) + alpha123 ( 1 + x4^2 ) ( e1 ∧ e2 ∧ e3 ∧ ē ) - ( x3^2 - x2^2 ) ( ad12 ( e1 ∧ e2 ∧ e ∧ ē ) + ad23 ( e2 ∧ e3 ∧ e ∧ ē ) + ad31 ( e3 ∧ e1 ∧ e ∧ ē ) ) - ( x1^2 - x3^2 ) ( bd12 ( e1 ∧ e2 ∧ e ∧ ē ) + bd23 ( e2 ∧ e3 ∧ e ∧ ē ) + bd31 ( e3 ∧ e1 ∧ e ∧ ē ) ) - ( x2^2 - x1^2 ) ( cd12 ( e1 ∧ e2 ∧ e ∧ ē ) + cd23 ( e2 ∧ e3 ∧ e ∧ ē ) + cd31 ( e3 ∧ e1 ∧ e ∧ ē ) ) - ( x4^2 - x3^2 ) ( ab12 ( e1 ∧ e2 ∧ e ∧ ē ) + ab23 ( e2 ∧ e3 ∧ e ∧ ē ) + ab31 ( e3 ∧ e1 ∧ e ∧ ē ) ) - ( x4^2 - x1^2 ) ( bc12 ( e1 ∧ e2 ∧ e ∧ ē ) + bc23 ( e2 ∧ e3 ∧ e ∧ ē ) + bc31 ( e3 ∧ e1 ∧ e ∧ ē ) ) - ( x4^2 - x2^2 ) ( ca12 ( e1 ∧ e2 ∧ e ∧ ē ) + ca23 ( e2 ∧ e3 ∧ e ∧ ē ) + ca31 ( e3 ∧ e1 ∧ e ∧ ē ) )",
    ),
    (
        "A.47",
        1,
        "- alpha1 beta1 e1e2e3 + alpha1 beta2 e2eē - alpha1 beta2 e2 - alpha1 beta3 e1eē - alpha1 beta3 e1 + alpha1 beta4 e3e1e - alpha1 beta5 e2e3e + alpha1 beta6 e + alpha1 beta1 e1e2e3 + alpha1 beta2 e2 - alpha1 beta2 e2eē + alpha1 beta3 e1 + alpha1 beta3 e1eē + alpha1 beta4 e3e1ē - alpha1 beta5 e2e3ē + alpha1 beta6 ē - alpha2 beta1 e2eē - alpha2 beta1 e2 - alpha2 beta2 e1e2e3 + alpha2 beta3 e3eē + alpha2 beta3 e3 + alpha2 beta4 e + alpha2 beta5 e1e2e - alpha2 beta6 e3e1e + alpha2 beta1 e2 + alpha2 beta1 e2eē + alpha2 beta2 e1e2e3 - alpha2 beta3 e3 - alpha2 beta3 e3eē + alpha2 beta4 ē + alpha2 beta5 e1e2ē - alpha2 beta6 e3e1ē + alpha3 beta1 e1eē + alpha3 beta1 e1 - alpha3 beta2 e3eē - alpha3 beta2 e3 - alpha3 beta3 e1e2e3 - alpha3 beta4 e1e2e + alpha3 beta5 e + alpha3 beta6 e2e3e - alpha3 beta1 e1 - alpha3 beta1 e1eē + alpha3 beta2 e3 + alpha3 beta2 e3eē + alpha3 beta3 e1e2e3 - alpha3 beta4 e1e2ē + alpha3 beta5 ē + alpha3 beta6 e2e3ē - alpha4 beta1 e3e1e - alpha4 beta1 e3e1ē + alpha4 beta2 e + alpha4 beta2 ē + alpha4 beta3 e1e2e + alpha4 beta3 e1e2ē - alpha4 beta5 e3eē + alpha4 beta6 e2eē + alpha5 beta1 e2e3e + alpha5 beta1 e2e3ē - alpha5 beta2 e1e2e - alpha5 beta2 e1e2ē + alpha5 beta3 e + alpha5 beta3 ē + alpha5 beta4 e3eē - alpha5 beta6 e1eē + alpha6 beta1 e + alpha6 beta1 ē + alpha6 beta2 e3e1e + alpha6 beta2 e3e1ē - alpha6 beta3 e2e3e - alpha6 beta3 e2e3ē - alpha6 beta4 e2eē + alpha6 beta5 e1eē",
    ),
    (
        "A.52",
        1,
        "omega1 e1e2e3e + omega1 e1e2e3ē - omega2 e1e2eē - omega3 e2e3eē - omega4 e3e1eē",
    ),
    (
        "A.100",
        1,
        "8 ( omega1 e1e2e3e + omega1 e1e2e3ē - omega2 e1e2eē - omega3 e2e3eē - omega4 e3e1eē )",
    ),
    (
        "A.53",
        1,
        "omega1 e1e2e3eēe1e2e3e + omega1 e1e2e3eēe1e2e3ē - omega2 e1e2e3eēe1e2eē - omega3 e1e2e3eēe2e3eē - omega4 e1e2e3eēe3e1eē",
    ),
    (
        "A.68",
        1,
        "lambda1 e1e2e3e + lambda1 e1e2e3ē - lambda2 e1e2eē - lambda3 e2e3eē - lambda4 e3e1eē",
    ),
    (
        "A.74",
        1,
        "omega1 e1e2e3e + omega1 e1e2e3ē - omega2 e1e2eē - omega3 e2e3eē - omega4 e3e1eē",
    ),
    (
        "A.55",
        1,
        "omega3 beta1 e2e + omega3 beta1 e2ē - omega3 beta3 e3e - omega3 beta3 e3ē - omega3 beta4 eē - omega4 beta1 e1e - omega4 beta1 e1ē + omega4 beta2 e3e + omega4 beta2 e3ē - omega4 beta5 eē - omega2 beta2 e2e - omega2 beta2 e2ē + omega2 beta3 e1e + omega2 beta3 e1ē - omega2 beta6 eē + omega1 beta1 e1e2 + omega1 beta2 e2e3 + omega1 beta3 e3e1 + omega1 beta4 e1ē + omega1 beta5 e2ē + omega1 beta6 e3ē - omega1 beta1 e1e2 - omega1 beta2 e2e3 - omega1 beta3 e3e1 + omega1 beta4 e1e + omega1 beta5 e2e + omega1 beta6 e3e",
    ),
    (
        "A.63",
        1,
        "mu4 beta1 e2e + mu4 beta1 e2ē - mu4 beta3 e3e - mu4 beta3 e3ē - mu4 beta4 eē - mu5 beta1 e1e - mu5 beta1 e1ē + mu5 beta2 e3e + mu5 beta2 e3ē - mu5 beta5 eē - mu3 beta2 e2e - mu3 beta2 e2ē + mu3 beta3 e1e + mu3 beta3 e1ē - mu3 beta6 eē + mu2 beta1 e1e2 + mu2 beta2 e2e3 + mu2 beta3 e3e1 + mu2 beta4 e1ē + mu2 beta5 e2ē + mu2 beta6 e3ē - mu1 beta1 e1e2 - mu1 beta2 e2e3 - mu1 beta3 e3e1 + mu1 beta4 e1e + mu1 beta5 e2e + mu1 beta6 e3e",
    ),
    (
        "A.69",
        1,
        "omega3 lambda1 e2e3e + omega3 lambda1 e2e3ē - omega3 lambda2 e2eē + omega3 lambda4 e3eē - omega4 lambda1 e1e3e - omega4 lambda1 e1e3ē + omega4 lambda2 e1eē - omega4 lambda3 e3eē + omega2 lambda1 e1e2e + omega2 lambda1 e1e2ē + omega2 lambda3 e2eē - omega2 lambda4 e1eē - omega1 lambda1 e1e2e3 - omega1 lambda2 e1e2ē - omega1 lambda3 e2e3ē - omega1 lambda4 e3e1ē + omega1 lambda1 e1e2e3 - omega1 lambda2 e1e2e - omega1 lambda3 e2e3e - omega1 lambda4 e3e1e",
    ),
    (
        "A.75",
        1,
        "mu4 omega1 e2e3e + mu4 omega1 e2e3ē - mu4 omega2 e2eē + mu4 omega4 e3eē - mu5 omega1 e1e3e - mu5 omega1 e1e3ē + mu5 omega2 e1eē - mu5 omega3 e3eē + mu3 omega1 e1e2e + mu3 omega1 e1e2ē + mu3 omega3 e2eē - mu3 omega4 e1eē - mu2 omega1 e1e2e3 - mu2 omega2 e1e2ē - mu2 omega3 e2e3ē - mu2 omega4 e3e1ē + mu1 omega1 e1e2e3 - mu1 omega2 e1e2e - mu1 omega3 e2e3e - mu1 omega4 e3e1e",
    ),
    (
        "A.81",
        1,
        "mu4 lambda1 e2e3e + mu4 lambda2 e2e3ē - mu4 lambda3 e2eē + mu4 lambda5 e3eē - mu5 lambda1 e1e3e - mu5 lambda2 e1e3ē + mu5 lambda3 e1eē - mu5 lambda4 e3eē + mu3 lambda1 e1e2e + mu3 lambda2 e1e2ē + mu3 lambda4 e2eē - mu3 lambda5 e1eē - mu2 lambda1 e1e2e3 - mu2 lambda3 e1e2ē - mu2 lambda4 e2e3ē - mu2 lambda5 e3e1ē + mu1 lambda2 e1e2e3 - mu1 lambda3 e1e2e - mu1 lambda4 e2e3e - mu1 lambda5 e3e1e",
    ),
    (
        "A.92",
        3,
        "2 x e3e1 + x^2 ( ee3e1 + ēe3e1 ) - ( ee3e1 - ēe3e1 ) - 2 e3e1 x - x^2 ( e3e1e + e3e1ē ) + e3e1e - e3e1ē",
    ),
    (
        "A.92",
        4,
        "( 2 x e3e1 - 2 e3e1 x )",
    ),
    (
        "A.93",
        1,
        "2 x co^2 + x^2 n co^2 - nbar co^2 - 2 e3e1 x e3e1 si^2 + n x^2 si^2 - nbar si^2 + ( 2 x e3e1 - 2 e3e1 x ) si co",
    ),
    (
        "A.98",
        1,
        "Pi_omega L_beta Pi_omega",
    ),
    (
        "A.102",
        1,
        "- omega1 beta1 e3 - omega1 beta1 e3eē - omega1 beta2 e1 - omega1 beta2 e1eē - omega1 beta3 e2 - omega1 beta3 e2eē + omega1 beta4 e2e3ē - omega1 beta5 e1e3ē + omega1 beta6 e1e2ē + omega1 beta1 e3eē + omega1 beta1 e3 + omega1 beta2 e1eē + omega1 beta2 e1 + omega1 beta3 e2eē + omega1 beta3 e2 + omega1 beta4 e2e3e - omega1 beta5 e1e3e + omega1 beta6 e1e2e - omega2 beta1 ē - omega2 beta1 e - omega2 beta2 e3e1ē - omega2 beta2 e3e1e + omega2 beta3 e2e3ē + omega2 beta3 e2e3e - omega2 beta4 e2 + omega2 beta5 e1 + omega2 beta6 e1e2e3 + omega3 beta1 e3e1ē + omega3 beta1 e3e1e - omega3 beta2 ē - omega3 beta2 e - omega3 beta3 e1e2ē - omega3 beta3 e1e2e + omega3 beta4 e1e2e3 - omega3 beta5 e3 + omega3 beta6 e2 - omega4 beta1 e2e3ē - omega4 beta1 e2e3e + omega4 beta2 e1e2ē + omega4 beta2 e1e2e - omega4 beta3 ē - omega4 beta3 e + omega4 beta4 e3 + omega4 beta5 e1e2e3 - omega4 beta6 e1",
    ),
    (
        "A.104",
        1,
        "Pi_omega L_beta Pi_omega",
    ),
];

/// The distinct errors: `(key, class, what is wrong)`. Entries name theirs in an `erratum` field;
/// the report counts keys, not entries, and says from the entries whether an error repeats.
pub const ERRATA: &[(&str, &str, &str)] = &[
    ("x2-d3", "misprint", "x2 is printed b1e1 + b2e2 + d3e3; it must be b3, as in (A.2) and every later formula"),
    ("meet-star", "notation slip", "B = (L1 ∨ L2)* carries a star that does not belong: (L1 ∨ L2)* has grade 4, B grade 1, and the other five intersections have no star"),
    ("B-grade-3", "formula", "the line–line B has grade-3 terms: it is ⟨(I L1) L2⟩₁₊₃, not the inner product, whose value is the grade-1 part (the one scalar of (II.54) is right)"),
    ("II.56-sign", "formula", "the e2ē coefficient has −ω1β5; it must be +ω1β5"),
    ("II.63-alpha", "misprint", "α234 and α314 misprinted (d1w2w3 for d1q2w3, w1c2w3 for q1c2w3); (II.62) is right with the correct α"),
    ("II.64-sign", "formula", "the e3e square (μ5β2 + μ1β6 − μ4β3)² must be subtracted, not added"),
    ("II.78-xref", "cross-reference slip", "“μ toma los mismos valores que (II.62)”: those μ belong to the sphere P3 … P6; E1 = P1 … P4 needs those of (II.72)"),
    ("II.79-x7", "misprint", "λ1 ends in α123(x7² − 1); it must be α123(x8² − 1)"),
    ("II.25-repeat", "misprint", "the second term repeats x1∧x2∧n∧n̄; it must be x1∧x3∧n∧n̄ ((A.23) is right)"),
    ("A.14-bracket", "misprint", "a misplaced bracket: the eē terms lose the factor 4 ((A.16) is right)"),
    ("rot-bare-axis", "formula", "the coordinate along the rotation axis is printed as the bare basis vector (coefficient 1); it keeps its coordinate ((II.40) is right)"),
    ("A.97-sign", "formula", "both sin·cos terms have the wrong sign for B = e1e2"),
    ("A.4-stray-n", "derivation slip", "the first line, “P1∧P2 = (…)∧(…)∧n”, ends in a stray ∧n"),
    ("A.4-nbar-n", "derivation slip", "the last term (n̄∧n) must be (n̄∧n̄) = 0 ((A.5) drops it)"),
    ("A.20-x1", "derivation slip", "−2x1(n∧n̄∧x3): x1 must be squared"),
    ("A.20-4x1", "derivation slip", "+4x1²(x2∧n∧n̄) must be +2x1²(x2∧n∧n̄)"),
    ("A.21-x3", "derivation slip", "4x3²(x1∧x2∧x3) must be 4x3²(x1∧x2∧n)"),
    ("A.35-x1", "derivation slip", "(4x1² − 4x3²)(x1∧n∧n̄∧x4) must have x2 ((II.26e) is right)"),
    ("A.36u-ebar", "derivation slip", "the ē terms carry α(1 − x²) like the e terms; they must carry α(1 + x²), and +α123(1 + x4²), as μ2 of (A.40) does (the overall factor 8 is dropped on purpose)"),
    ("A.47-terms", "derivation slip", "the second −α1β2 e2 must be +α1β2 e2, and the last term +α6β3 e1e2e3 does not belong"),
    ("omega2-for-omega4", "misprint", "the plane’s e3e1eē coefficient is printed −ω2 (−λ2 in (A.68)); it must be −ω4 (−λ4), as in (A.31) and as (A.54) uses"),
    ("A.55-terms", "derivation slip", "ω3β3 e1e and ω3β4 e1ē must both be ω2β3"),
    ("A.63-terms", "derivation slip", "−μ3β1 e2e must be −μ3β2 e2e, and −μ4β3 eē must be −μ4β4 eē"),
    ("A.69-term", "derivation slip", "the second −ω1λ2 e1e2ē must be −ω1λ2 e1e2e"),
    ("A.75-term", "derivation slip", "−μ1ω2 e1e2ē must be −μ1ω2 e1e2e"),
    ("A.81-term", "derivation slip", "−μ5λ1 e1e3ē must be −μ5λ1 e1e3e"),
    ("A.92-sign", "derivation slip", "(ee3e1 − ēe3e1) comes from −n̄e3e1 and must enter with −, not +"),
    ("A.92-sincos", "derivation slip", "the last step multiplies XB − BX by sin α cos α, which the left side does not have"),
    ("A.93-ebar", "derivation slip", "a stray +ē"),
    ("A.98-order", "notation slip", "L′ = LPL: the reflection of L in the plane P is P L P, what (A.104) computes"),
    ("A.102-sign", "derivation slip", "−ω2β3 e2e3e must be +ω2β3 e2e3e"),
    ("A.104-terms", "derivation slip", "several terms of the expansion are wrong (the blades listed; the correction shown is the product itself); (A.105), the part kept, is right"),
];

/// Entries whose corrected formula is another entry's (the same display printed twice).
pub const CORRECTION_AS: &[(&str, &str)] =
    &[("A.48", "II.53"), ("A.56", "II.56"), ("A.65", "II.64")];

/// Corrected auxiliary definitions `(equation, symbol, definition)`.
pub const CORRECTED_LETS: &[(&str, &str, &str)] = &[
    (
        "II.63",
        "alpha234",
        "d1*q2*w3 + d2*q3*w1 + d3*q1*w2 - d2*q1*w3 - d3*q2*w1 - d1*q3*w2",
    ),
    (
        "II.63",
        "alpha314",
        "q1*c2*w3 + q2*c3*w1 + q3*c1*w2 - q2*c1*w3 - q3*c2*w1 - q1*c3*w2",
    ),
    (
        "II.79",
        "lambda1",
        "alpha124(1 - x7^2) + alpha234(1 - x5^2) + alpha314(1 - x6^2) + alpha123(x8^2 - 1)",
    ),
];

/// Corrected `uses` (which section's symbols a formula takes).
pub const CORRECTED_USES: &[(&str, &str)] = &[
    ("II.78", "II.72, II.73, II.79, II.80"),
    ("II.78d", "II.72, II.73"),
];

pub(crate) fn lookup2<'a>(table: &'a [(&str, &str)], id: &str) -> Option<&'a str> {
    table.iter().find(|(k, _)| *k == id).map(|(_, v)| *v)
}
