//! The pack/unpack functions (`packUnorm4x8`, `unpackHalf2x16`, ...) for
//! the GL modules. GLSL 330 has none of them, ES 300 lacks the 4x8 ones,
//! and naga's fallbacks for the unpacks skip the clamp of the snorm ones,
//! so every GL module computes all ten from bit operations, with the
//! arithmetic WGSL defines (`floor(0.5 + 255 * clamp(x, 0, 1))`, ...),
//! which is also what the WGSL and SPIR-V targets run natively. The half
//! conversions round to nearest, ties to even, and keep infinities and
//! NaNs (a NaN becomes a quiet one).

use naga::{BinaryOperator as Bo, Expression as E, Handle, MathFunction as Mf};

use super::function::FnBuilder;
use super::types::vector_size;
use crate::sema::{Scalar, Ty};
use crate::source::Span;

/// A normalised pack's lanes: count, bits per lane, scale, signed.
fn norm_format(fun: Mf) -> Option<(u8, u32, f32, bool)> {
    Some(match fun {
        Mf::Pack4x8unorm | Mf::Unpack4x8unorm => (4, 8, 255.0, false),
        Mf::Pack4x8snorm | Mf::Unpack4x8snorm => (4, 8, 127.0, true),
        Mf::Pack2x16unorm | Mf::Unpack2x16unorm => (2, 16, 65535.0, false),
        Mf::Pack2x16snorm | Mf::Unpack2x16snorm => (2, 16, 32767.0, true),
        _ => return None,
    })
}

impl FnBuilder<'_, '_> {
    pub(super) fn pack_gl(&mut self, fun: Mf, x: Handle<E>, s: Span) -> Handle<E> {
        match fun {
            Mf::Pack2x16float => {
                let lo = self.append(E::AccessIndex { base: x, index: 0 }, s);
                let hi = self.append(E::AccessIndex { base: x, index: 1 }, s);
                let (lo, hi) = (self.f32_to_f16_bits(lo, s), self.f32_to_f16_bits(hi, s));
                let hi = self.bin_u(Bo::ShiftLeft, hi, 16, s);
                self.append(E::Binary { op: Bo::InclusiveOr, left: lo, right: hi }, s)
            }
            Mf::Unpack2x16float => {
                let lo = self.bin_u(Bo::And, x, 0xFFFF, s);
                let hi = self.bin_u(Bo::ShiftRight, x, 16, s);
                let (lo, hi) = (self.f16_bits_to_f32(lo, s), self.f16_bits_to_f32(hi, s));
                let ty = self.m.ty(&Ty::Vector(Scalar::Float, 2));
                self.append(E::Compose { ty, components: vec![lo, hi] }, s)
            }
            Mf::Pack4x8unorm | Mf::Pack4x8snorm | Mf::Pack2x16unorm | Mf::Pack2x16snorm => {
                let (n, bits, scale, signed) = norm_format(fun).expect("a normalised pack");
                // floor(0.5 + scale * clamp(x, lo, 1)), lane by lane.
                let lo = self.splat_f(if signed { -1.0 } else { 0.0 }, n, s);
                let one = self.splat_f(1.0, n, s);
                let c = self.math(Mf::Clamp, &[x, lo, one], s);
                let k = self.splat_f(scale, n, s);
                let scaled = self.append(E::Binary { op: Bo::Multiply, left: k, right: c }, s);
                let half = self.splat_f(0.5, n, s);
                let t = self.append(E::Binary { op: Bo::Add, left: half, right: scaled }, s);
                let t = self.math(Mf::Floor, &[t], s);
                // To the lanes' integer bits (an int keeps the two's complement).
                let ints = if signed {
                    let i = self.append(E::As { expr: t, kind: naga::ScalarKind::Sint, convert: Some(4) }, s);
                    self.append(E::As { expr: i, kind: naga::ScalarKind::Uint, convert: None }, s)
                } else {
                    self.append(E::As { expr: t, kind: naga::ScalarKind::Uint, convert: Some(4) }, s)
                };
                let mask = (1u32 << bits) - 1;
                let mut packed = None;
                for i in 0..n {
                    let lane = self.append(E::AccessIndex { base: ints, index: i as u32 }, s);
                    let lane = self.bin_u(Bo::And, lane, mask, s);
                    let lane = if i == 0 { lane } else { self.bin_u(Bo::ShiftLeft, lane, bits * i as u32, s) };
                    packed = Some(match packed {
                        None => lane,
                        Some(p) => self.append(E::Binary { op: Bo::InclusiveOr, left: p, right: lane }, s),
                    });
                }
                packed.expect("two or four lanes")
            }
            Mf::Unpack4x8unorm | Mf::Unpack4x8snorm | Mf::Unpack2x16unorm | Mf::Unpack2x16snorm => {
                let (n, bits, scale, signed) = norm_format(fun).expect("a normalised unpack");
                let mut lanes = Vec::with_capacity(n as usize);
                for i in 0..n as u32 {
                    let lane = if signed {
                        // Shift the lane to the top, then arithmetically back:
                        // its sign is extended.
                        let up = if 32 - bits * (i + 1) == 0 { x } else { self.bin_u(Bo::ShiftLeft, x, 32 - bits * (i + 1), s) };
                        let up = self.append(E::As { expr: up, kind: naga::ScalarKind::Sint, convert: None }, s);
                        let amount = self.literal(naga::Literal::U32(32 - bits), s);
                        let v = self.append(E::Binary { op: Bo::ShiftRight, left: up, right: amount }, s);
                        self.append(E::As { expr: v, kind: naga::ScalarKind::Float, convert: Some(4) }, s)
                    } else {
                        let down = if i == 0 { x } else { self.bin_u(Bo::ShiftRight, x, bits * i, s) };
                        let v = self.bin_u(Bo::And, down, (1u32 << bits) - 1, s);
                        self.append(E::As { expr: v, kind: naga::ScalarKind::Float, convert: Some(4) }, s)
                    };
                    lanes.push(lane);
                }
                let ty = self.m.ty(&Ty::Vector(Scalar::Float, n));
                let v = self.append(E::Compose { ty, components: lanes }, s);
                let k = self.splat_f(scale, n, s);
                let v = self.append(E::Binary { op: Bo::Divide, left: v, right: k }, s);
                if signed {
                    // -128 / 127 is below -1: WGSL and GLSL clamp it.
                    let lo = self.splat_f(-1.0, n, s);
                    self.math(Mf::Max, &[v, lo], s)
                } else {
                    v
                }
            }
            _ => unreachable!("only pack and unpack functions reach pack_gl"),
        }
    }

    /// `x op k` with a `uint` literal `k`.
    fn bin_u(&mut self, op: Bo, x: Handle<E>, k: u32, s: Span) -> Handle<E> {
        let k = self.literal(naga::Literal::U32(k), s);
        self.append(E::Binary { op, left: x, right: k }, s)
    }

    fn splat_f(&mut self, v: f32, n: u8, s: Span) -> Handle<E> {
        let v = self.literal(naga::Literal::F32(v), s);
        self.append(E::Splat { size: vector_size(n), value: v }, s)
    }

    fn select(&mut self, condition: Handle<E>, accept: Handle<E>, reject: Handle<E>, s: Span) -> Handle<E> {
        self.append(E::Select { condition, accept, reject }, s)
    }

    /// The binary16 bits (in the low half of a `uint`) of an `f32`: round
    /// to nearest even; overflow to infinity; NaN to a quiet NaN. The
    /// subnormal results are rounded by one float addition of a magic
    /// number whose exponent puts the binary16 subnormal's last bit at the
    /// float's last mantissa bit (F. Giesen's method); GLSL rounds `+` to
    /// nearest.
    fn f32_to_f16_bits(&mut self, f: Handle<E>, s: Span) -> Handle<E> {
        let u = self.append(E::As { expr: f, kind: naga::ScalarKind::Uint, convert: None }, s);
        let sign = self.bin_u(Bo::And, u, 0x8000_0000, s);
        let a = self.bin_u(Bo::And, u, 0x7FFF_FFFF, s);
        // Infinity or NaN, or too large for binary16.
        let f32_inf = self.literal(naga::Literal::U32(0x7F80_0000), s);
        let is_nan = self.append(E::Binary { op: Bo::Greater, left: a, right: f32_inf }, s);
        let q_nan = self.literal(naga::Literal::U32(0x7E00), s);
        let inf = self.literal(naga::Literal::U32(0x7C00), s);
        let special = self.select(is_nan, q_nan, inf, s);
        // Below binary16's smallest normal: add the magic, subtract its bits.
        let magic_bits = ((127 - 15) + (23 - 10) + 1) << 23;
        let af = self.append(E::As { expr: a, kind: naga::ScalarKind::Float, convert: None }, s);
        let magic = self.literal(naga::Literal::F32(f32::from_bits(magic_bits)), s);
        let sum = self.append(E::Binary { op: Bo::Add, left: af, right: magic }, s);
        let sum = self.append(E::As { expr: sum, kind: naga::ScalarKind::Uint, convert: None }, s);
        let subnormal = self.bin_u(Bo::Subtract, sum, magic_bits, s);
        // Normal: rebias the exponent and round the 13 dropped bits to
        // nearest, ties to the even mantissa.
        let odd = self.bin_u(Bo::ShiftRight, a, 13, s);
        let odd = self.bin_u(Bo::And, odd, 1, s);
        let rebias = self.bin_u(Bo::Add, a, ((15u32.wrapping_sub(127)) << 23).wrapping_add(0xFFF), s);
        let rounded = self.append(E::Binary { op: Bo::Add, left: rebias, right: odd }, s);
        let normal = self.bin_u(Bo::ShiftRight, rounded, 13, s);
        // Which of the three.
        let f16_max = self.literal(naga::Literal::U32((127 + 16) << 23), s);
        let too_large = self.append(E::Binary { op: Bo::GreaterEqual, left: a, right: f16_max }, s);
        let f16_min_normal = self.literal(naga::Literal::U32(113 << 23), s);
        let small = self.append(E::Binary { op: Bo::Less, left: a, right: f16_min_normal }, s);
        let finite = self.select(small, subnormal, normal, s);
        let h = self.select(too_large, special, finite, s);
        let sign16 = self.bin_u(Bo::ShiftRight, sign, 16, s);
        self.append(E::Binary { op: Bo::InclusiveOr, left: h, right: sign16 }, s)
    }

    /// The `f32` of binary16 bits (the low half of a `uint`); exact.
    fn f16_bits_to_f32(&mut self, h: Handle<E>, s: Span) -> Handle<E> {
        let magnitude = self.bin_u(Bo::And, h, 0x7FFF, s);
        let shifted = self.bin_u(Bo::ShiftLeft, magnitude, 13, s);
        let exp = self.bin_u(Bo::And, shifted, 0x7C00 << 13, s);
        let o = self.bin_u(Bo::Add, shifted, (127 - 15) << 23, s);
        // Infinity or NaN: the largest exponent.
        let special = self.bin_u(Bo::Add, o, (128 - 16) << 23, s);
        // Zero or subnormal: renormalise by one exact float subtraction.
        let one_more = self.bin_u(Bo::Add, o, 1 << 23, s);
        let one_more = self.append(E::As { expr: one_more, kind: naga::ScalarKind::Float, convert: None }, s);
        let magic = self.literal(naga::Literal::F32(f32::from_bits(113 << 23)), s);
        let renorm = self.append(E::Binary { op: Bo::Subtract, left: one_more, right: magic }, s);
        let renorm = self.append(E::As { expr: renorm, kind: naga::ScalarKind::Uint, convert: None }, s);
        let exp_max = self.literal(naga::Literal::U32(0x7C00 << 13), s);
        let is_special = self.append(E::Binary { op: Bo::Equal, left: exp, right: exp_max }, s);
        let zero = self.literal(naga::Literal::U32(0), s);
        let is_small = self.append(E::Binary { op: Bo::Equal, left: exp, right: zero }, s);
        let o = self.select(is_small, renorm, o, s);
        let o = self.select(is_special, special, o, s);
        let sign = self.bin_u(Bo::And, h, 0x8000, s);
        let sign = self.bin_u(Bo::ShiftLeft, sign, 16, s);
        let bits = self.append(E::Binary { op: Bo::InclusiveOr, left: o, right: sign }, s);
        self.append(E::As { expr: bits, kind: naga::ScalarKind::Float, convert: None }, s)
    }
}
