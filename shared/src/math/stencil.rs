//! A CPU model of the stencil test and of every stencil operation, with its masks: what the GPU does
//! to one pixel's stored stencil value when a fragment arrives. The book's worked examples use it, and
//! the truth-table test checks the GPU against it, case by case.
//!
//! The names follow wgpu; D3D11 and OpenGL do the same under other names (see the stencil chapter).

use wgpu::{CompareFunction, StencilFaceState, StencilOperation};

/// The eight stencil operations, by the names the knobs use.
pub const OPERATION_VALUES: &[&str] = &[
    "keep",
    "zero",
    "replace",
    "invert",
    "increment-clamp",
    "decrement-clamp",
    "increment-wrap",
    "decrement-wrap",
];

/// Every stencil operation, in wgpu's order.
pub const OPERATIONS: [StencilOperation; 8] = [
    StencilOperation::Keep,
    StencilOperation::Zero,
    StencilOperation::Replace,
    StencilOperation::Invert,
    StencilOperation::IncrementClamp,
    StencilOperation::DecrementClamp,
    StencilOperation::IncrementWrap,
    StencilOperation::DecrementWrap,
];

/// Every comparison function, in wgpu's order.
pub const COMPARISONS: [CompareFunction; 8] = [
    CompareFunction::Never,
    CompareFunction::Less,
    CompareFunction::Equal,
    CompareFunction::LessEqual,
    CompareFunction::Greater,
    CompareFunction::NotEqual,
    CompareFunction::GreaterEqual,
    CompareFunction::Always,
];

/// A stencil operation by the name the knobs use.
///
/// # Panics
/// On a name outside [`OPERATION_VALUES`]: knob values are checked before a lesson sees them.
pub fn operation(name: &str) -> StencilOperation {
    let index = OPERATION_VALUES
        .iter()
        .position(|n| *n == name)
        .unwrap_or_else(|| panic!("not a stencil operation: {name}"));
    OPERATIONS[index]
}

// ANCHOR: test
/// The stencil test: `(reference & read_mask) CMP (stored & read_mask)`.
///
/// The reference is on the left: `Less` passes when the masked reference is less than the masked
/// stored value. The read mask cuts the same bits from both sides.
pub fn passes(compare: CompareFunction, reference: u8, read_mask: u8, stored: u8) -> bool {
    let (left, right) = (reference & read_mask, stored & read_mask);
    match compare {
        CompareFunction::Never => false,
        CompareFunction::Less => left < right,
        CompareFunction::Equal => left == right,
        CompareFunction::LessEqual => left <= right,
        CompareFunction::Greater => left > right,
        CompareFunction::NotEqual => left != right,
        CompareFunction::GreaterEqual => left >= right,
        CompareFunction::Always => true,
    }
}
// ANCHOR_END: test

// ANCHOR: operation
/// The value an operation computes from the stored value (before the write mask).
pub fn apply(operation: StencilOperation, stored: u8, reference: u8) -> u8 {
    match operation {
        StencilOperation::Keep => stored,
        StencilOperation::Zero => 0,
        StencilOperation::Replace => reference,
        StencilOperation::Invert => !stored,
        StencilOperation::IncrementClamp => stored.saturating_add(1),
        StencilOperation::DecrementClamp => stored.saturating_sub(1),
        StencilOperation::IncrementWrap => stored.wrapping_add(1),
        StencilOperation::DecrementWrap => stored.wrapping_sub(1),
    }
}

/// The write mask picks which bits of the new value reach the buffer; the others keep their old bits.
pub fn write(stored: u8, new: u8, write_mask: u8) -> u8 {
    (stored & !write_mask) | (new & write_mask)
}
// ANCHOR_END: operation

/// Everything that decides what a fragment does to one pixel's stencil value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Case {
    pub face: StencilFaceState,
    pub reference: u8,
    pub read_mask: u8,
    pub write_mask: u8,
    pub stored: u8,
    /// Whether the fragment passes the depth test.
    pub depth_passes: bool,
}

// ANCHOR: outcome
impl Case {
    /// The value the pixel holds after the fragment: the stencil test picks `fail_op`; if it passes,
    /// the depth test picks `depth_fail_op` or `pass_op`; the write mask merges the result.
    pub fn outcome(&self) -> u8 {
        let face = &self.face;
        let operation = if !passes(face.compare, self.reference, self.read_mask, self.stored) {
            face.fail_op
        } else if !self.depth_passes {
            face.depth_fail_op
        } else {
            face.pass_op
        };
        let new = apply(operation, self.stored, self.reference);
        write(self.stored, new, self.write_mask)
    }
}
// ANCHOR_END: outcome

#[cfg(test)]
mod tests {
    use super::*;

    fn face(compare: CompareFunction, pass_op: StencilOperation) -> StencilFaceState {
        StencilFaceState {
            compare,
            fail_op: StencilOperation::Keep,
            depth_fail_op: StencilOperation::Keep,
            pass_op,
        }
    }

    #[test]
    fn reference_is_on_the_left() {
        // ref 1 < stored 2
        assert!(passes(CompareFunction::Less, 1, 0xff, 2));
        assert!(!passes(CompareFunction::Greater, 1, 0xff, 2));
    }

    /// Each compare function with the reference below, equal to and above the stored value.
    #[test]
    fn every_compare_function() {
        use CompareFunction as C;
        let cases = [
            (C::Never, [false, false, false]),
            (C::Less, [true, false, false]),
            (C::Equal, [false, true, false]),
            (C::LessEqual, [true, true, false]),
            (C::Greater, [false, false, true]),
            (C::NotEqual, [true, false, true]),
            (C::GreaterEqual, [false, true, true]),
            (C::Always, [true, true, true]),
        ];
        for (compare, expected) in cases {
            let got = [1, 2, 3].map(|reference| passes(compare, reference, 0xff, 2));
            assert_eq!(got, expected, "{compare:?}");
        }
    }

    #[test]
    fn read_mask_cuts_both_sides() {
        // 0x12 & 0x0f = 0x02 and 0x32 & 0x0f = 0x02: equal once the high bits are masked off.
        assert!(passes(CompareFunction::Equal, 0x12, 0x0f, 0x32));
        assert!(!passes(CompareFunction::Equal, 0x12, 0xff, 0x32));
        // A zero read mask makes every comparison 0 CMP 0.
        assert!(passes(CompareFunction::LessEqual, 200, 0, 3));
        assert!(!passes(CompareFunction::Less, 200, 0, 3));
    }

    #[test]
    fn operations_clamp_and_wrap() {
        use StencilOperation::*;
        assert_eq!(apply(IncrementClamp, 255, 0), 255);
        assert_eq!(apply(IncrementWrap, 255, 0), 0);
        assert_eq!(apply(DecrementClamp, 0, 0), 0);
        assert_eq!(apply(DecrementWrap, 0, 0), 255);
        assert_eq!(apply(Invert, 0b1010_0000, 0), 0b0101_1111);
        assert_eq!(apply(Replace, 9, 42), 42);
        assert_eq!(apply(Zero, 9, 42), 0);
        assert_eq!(apply(Keep, 9, 42), 9);
    }

    #[test]
    fn write_mask_keeps_the_unmasked_bits() {
        assert_eq!(write(0b1111_0000, 0b0000_1111, 0b0011_1100), 0b1100_1100);
    }

    #[test]
    fn a_case_runs_the_right_operation() {
        let mut case = Case {
            face: StencilFaceState {
                compare: CompareFunction::Equal,
                fail_op: StencilOperation::Zero,
                depth_fail_op: StencilOperation::Invert,
                pass_op: StencilOperation::IncrementClamp,
            },
            reference: 1,
            read_mask: 0xff,
            write_mask: 0xff,
            stored: 1,
            depth_passes: true,
        };
        assert_eq!(case.outcome(), 2);
        case.depth_passes = false;
        assert_eq!(case.outcome(), 0xfe);
        case.stored = 5;
        assert_eq!(case.outcome(), 0);
        let marked = Case {
            face: face(CompareFunction::Always, StencilOperation::Replace),
            depth_passes: true,
            ..case
        };
        assert_eq!(marked.outcome(), 1);
        // A fragment hidden by depth leaves the mark alone (depth_fail_op is Keep).
        let hidden = Case {
            depth_passes: false,
            ..marked
        };
        assert_eq!(hidden.outcome(), 5);
    }

    #[test]
    fn names_match_operations() {
        for (name, op) in OPERATION_VALUES.iter().zip(OPERATIONS) {
            assert_eq!(operation(name), op);
        }
    }
}
