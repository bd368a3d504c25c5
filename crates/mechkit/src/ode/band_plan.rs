//! Whether to factor a Newton matrix `c I − J` (or `I − c J`) as a band matrix, and in which
//! order of the unknowns.
//!
//! The matrix's pattern is the Jacobian's ([`JacobianPattern`]) and its diagonal. A second-order
//! system's state `[q, v]` puts `∂a/∂q` `n` places below the diagonal, so the pattern is
//! reordered first: by reverse Cuthill–McKee (George & Liu, *Computer Solution of Large Sparse
//! Positive Definite Systems*, 1981, Sec. 4.3) on the symmetrised graph, starting each
//! connected piece from a pseudo-peripheral node, which for a chain interleaves `qᵢ` and `vᵢ`.
//! Of the given order and the reordered one, the one with the cheaper banded factorisation is
//! kept, and it is used when that costs fewer operations than the dense one:
//! `n kl (kl + ku + 1) < n³ / 3`. Otherwise the matrix is factored dense, as without a pattern.

use std::collections::VecDeque;

use super::pattern::JacobianPattern;

/// A banded factorisation's plan: the order of the unknowns and the band in that order.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct BandPlan {
    /// `order[k]`: the unknown solved for in place `k`.
    pub order: Vec<usize>,
    /// Sub-diagonals of the reordered matrix.
    pub kl: usize,
    /// Super-diagonals of the reordered matrix.
    pub ku: usize,
}

impl BandPlan {
    /// The plan for a Newton matrix with the Jacobian pattern `p`, or `None` when the dense
    /// factorisation is cheaper.
    pub fn choose(p: &JacobianPattern) -> Option<BandPlan> {
        let n = p.dim();
        let natural: Vec<usize> = (0..n).collect();
        let best = [natural, reverse_cuthill_mckee(p)]
            .into_iter()
            .map(|order| {
                let (kl, ku) = bandwidths(p, &order);
                BandPlan { order, kl, ku }
            })
            .min_by_key(BandPlan::cost)?;
        let dense = (n * n * n) as f64 / 3.0;
        ((best.cost() as f64) < dense).then_some(best)
    }

    /// Multiply-adds of one factorisation, about.
    pub fn cost(&self) -> usize {
        self.order.len() * self.kl.max(1) * (self.kl + self.ku + 1)
    }
}

/// The lower and upper bandwidths of `p` (and its diagonal) with the unknowns in `order`.
pub(crate) fn bandwidths(p: &JacobianPattern, order: &[usize]) -> (usize, usize) {
    let mut place = vec![0; order.len()];
    for (k, &i) in order.iter().enumerate() {
        place[i] = k;
    }
    p.entries().fold((0, 0), |(kl, ku), (r, c)| {
        let (r, c) = (place[r], place[c]);
        (kl.max(r.saturating_sub(c)), ku.max(c.saturating_sub(r)))
    })
}

/// The reverse Cuthill–McKee order of `p`'s symmetrised graph.
fn reverse_cuthill_mckee(p: &JacobianPattern) -> Vec<usize> {
    let n = p.dim();
    let mut adj = vec![Vec::new(); n];
    for (r, c) in p.entries().filter(|(r, c)| r != c) {
        adj[r].push(c);
        adj[c].push(r);
    }
    for a in &mut adj {
        a.sort_unstable();
        a.dedup();
    }
    let degree = |i: usize| adj[i].len();
    let mut order = Vec::with_capacity(n);
    let mut placed = vec![false; n];
    let mut by_degree: Vec<usize> = (0..n).collect();
    by_degree.sort_by_key(|&i| degree(i));
    for &seed in &by_degree {
        if placed[seed] {
            continue;
        }
        let start = peripheral(&adj, seed);
        let mut queue = VecDeque::from([start]);
        placed[start] = true;
        while let Some(i) = queue.pop_front() {
            order.push(i);
            let mut next: Vec<usize> = adj[i].iter().copied().filter(|&j| !placed[j]).collect();
            next.sort_by_key(|&j| (degree(j), j));
            for j in next {
                placed[j] = true;
                queue.push_back(j);
            }
        }
    }
    order.reverse();
    order
}

/// A pseudo-peripheral node of `seed`'s connected piece: the farthest node of a breadth-first
/// search, of least degree, repeated while the eccentricity grows (George & Liu).
fn peripheral(adj: &[Vec<usize>], seed: usize) -> usize {
    let mut node = seed;
    let mut depth = 0;
    let mut level = vec![usize::MAX; adj.len()];
    loop {
        level.fill(usize::MAX);
        level[node] = 0;
        let mut queue = VecDeque::from([node]);
        let mut far = node;
        while let Some(i) = queue.pop_front() {
            for &j in &adj[i] {
                if level[j] == usize::MAX {
                    level[j] = level[i] + 1;
                    queue.push_back(j);
                    let better = level[j] > level[far]
                        || (level[j] == level[far] && adj[j].len() < adj[far].len());
                    if better {
                        far = j;
                    }
                }
            }
        }
        if level[far] <= depth {
            return node;
        }
        (node, depth) = (far, level[far]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pattern of a chain of `n` masses, `[q, v]`: `aᵢ` depends on neighbours.
    fn chain(n: usize) -> JacobianPattern {
        let mut a = JacobianPattern::new(n);
        for i in 0..n {
            for j in i.saturating_sub(1)..(i + 2).min(n) {
                a.insert(i, j);
            }
        }
        a.second_order(0)
    }

    #[test]
    fn a_chain_is_reordered_into_a_narrow_band() {
        let p = chain(20);
        assert_eq!(bandwidths(&p, &(0..40).collect::<Vec<_>>()), (21, 20));
        let plan = BandPlan::choose(&p).expect("banded");
        let mut sorted = plan.order.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..40).collect::<Vec<_>>());
        assert!(plan.kl + plan.ku < 7, "{plan:?}");
        assert_eq!(bandwidths(&p, &plan.order), (plan.kl, plan.ku));
    }

    #[test]
    fn dense_and_small_systems_stay_dense() {
        // van der Pol: [[0, 1], [x, x]]
        let mut one = JacobianPattern::new(1);
        one.insert(0, 0);
        assert_eq!(BandPlan::choose(&one.second_order(0)), None);
        let mut full = JacobianPattern::new(7);
        for r in 0..7 {
            for c in 0..7 {
                full.insert(r, c);
            }
        }
        assert_eq!(BandPlan::choose(&full.second_order(0)), None);
    }

    #[test]
    fn uncoupled_extras_cost_nothing() {
        // a chain with ten work components after it: their rows and columns are empty
        let mut a = JacobianPattern::new(10);
        for i in 0..10_usize {
            for j in i.saturating_sub(1)..(i + 2).min(10) {
                a.insert(i, j);
            }
        }
        let p = a.second_order(10);
        assert_eq!(p.dim(), 30);
        let plan = BandPlan::choose(&p).expect("banded");
        assert!(plan.kl + plan.ku < 7, "{plan:?}");
    }
}
