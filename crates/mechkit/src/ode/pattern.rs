//! The sparsity pattern of a Jacobian: which `∂fᵢ/∂yⱼ` may be non-zero. A system that knows
//! it ([`OdeSystem::jacobian_pattern`](super::OdeSystem::jacobian_pattern)) lets the
//! implicit methods factor their Newton matrices as band matrices in a reordering of the
//! unknowns ([`super::band_plan`]).

/// The entries of an `n × n` matrix that may be non-zero (the others are structurally zero:
/// zero for every state and time).
///
/// # Example
/// A chain of three masses, each pulled by its neighbours, as a second-order system
/// `y = [q, v]`:
/// ```
/// use mechkit::ode::JacobianPattern;
///
/// let mut a = JacobianPattern::new(3);
/// for i in 0..3_usize {
///     for j in i.saturating_sub(1)..(i + 2).min(3) {
///         a.insert(i, j);
///     }
/// }
/// assert_eq!(a.len(), 7);
/// let p = a.second_order(0);
/// assert_eq!(p.dim(), 6);
/// assert!(p.contains(0, 3)); // q₀' = v₀
/// assert!(p.contains(3, 1) && p.contains(3, 4)); // a₀ depends on q₁ and v₁
/// assert!(!p.contains(3, 2)); // but not on q₂
/// assert_eq!(p.len(), 3 + 2 * 7);
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct JacobianPattern {
    n: usize,
    /// The columns of each row's entries, sorted and without repeats.
    rows: Vec<Vec<usize>>,
}

impl JacobianPattern {
    /// A pattern of size `n` with no entries.
    pub fn new(n: usize) -> Self {
        Self {
            n,
            rows: vec![Vec::new(); n],
        }
    }

    /// The size of the matrix.
    pub fn dim(&self) -> usize {
        self.n
    }

    /// Marks `(row, col)` as possibly non-zero.
    ///
    /// # Panics
    /// When `row` or `col` is not below [`JacobianPattern::dim`].
    pub fn insert(&mut self, row: usize, col: usize) {
        assert!(
            row < self.n && col < self.n,
            "entry ({row}, {col}) outside a {n} × {n} pattern",
            n = self.n
        );
        let cols = &mut self.rows[row];
        if let Err(at) = cols.binary_search(&col) {
            cols.insert(at, col);
        }
    }

    /// Whether `(row, col)` may be non-zero.
    pub fn contains(&self, row: usize, col: usize) -> bool {
        self.rows
            .get(row)
            .is_some_and(|cols| cols.binary_search(&col).is_ok())
    }

    /// Every possibly non-zero entry, row by row.
    pub fn entries(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.rows
            .iter()
            .enumerate()
            .flat_map(|(r, cols)| cols.iter().map(move |&c| (r, c)))
    }

    /// The columns of row `row`'s possibly non-zero entries, sorted.
    pub(crate) fn row(&self, row: usize) -> &[usize] {
        &self.rows[row]
    }

    /// The number of possibly non-zero entries.
    pub fn len(&self) -> usize {
        self.rows.iter().map(Vec::len).sum()
    }

    /// Whether no entry may be non-zero.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The pattern of a second-order system's first-order form `y = [q, v, e]` with
    /// `y' = [v, a(t, q, v), g]`: `[[0, I, 0], [A, A, 0], [0, 0, 0]]`, where `self`
    /// (of size `dof`) marks the coordinates `j` that the acceleration `aᵢ` depends on,
    /// through `qⱼ` or `vⱼ`, and `extra` components `e` follow whose rows are taken as zero
    /// (quantities carried along that do not act back on the motion, like works).
    #[must_use]
    pub fn second_order(&self, extra: usize) -> JacobianPattern {
        let n = self.n;
        let mut p = JacobianPattern::new(2 * n + extra);
        for i in 0..n {
            p.rows[i].push(n + i);
            let row = &mut p.rows[n + i];
            row.extend(self.rows[i].iter().copied());
            row.extend(self.rows[i].iter().map(|c| n + c));
        }
        p
    }
}
