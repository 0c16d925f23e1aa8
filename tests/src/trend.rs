//! Memory judged by its trend over many samples, not by two points (the soak test's judge, and the
//! web edition's long session's).

/// The growth a steady leak gives `samples`: the median step from one sample to the next, times
/// the number of steps; and the largest single step, for the report. The median is the upper one
/// of an even count.
///
/// A leak moves every step, so it moves the median; a block taken or given back once (an
/// allocator's arena, a driver's working memory, a garbage collector's timing) moves one or two
/// steps of ten, which the median does not see.
pub fn trend(samples: &[i64]) -> (i64, i64) {
    let mut steps: Vec<i64> = samples.windows(2).map(|w| w[1] - w[0]).collect();
    steps.sort_unstable();
    let median = steps.get(steps.len() / 2).copied().unwrap_or(0);
    let largest = steps.last().copied().unwrap_or(0);
    (median * steps.len() as i64, largest)
}
