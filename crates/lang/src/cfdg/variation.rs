//! Variation codes as Context Free writes them (Mark Lentczner and John
//! Horigan, `variation.cpp`, Context Free 3.4): a code of letters is a
//! bijective base-26 number (`A` = 1, `Z` = 26, `AA` = 27, …), or a decimal
//! number; the number seeds the renderer's first random stream.

/// The variation number of `code` (`Variation::fromString`): letters (either
/// case) in bijective base 26, or a positive decimal number; `None` when the
/// code is empty, has other characters, or exceeds `i32::MAX`.
pub fn from_code(code: &str) -> Option<i32> {
    let code = code.trim_start();
    let first = code.chars().next()?;
    if !first.is_ascii_alphanumeric() {
        return None;
    }
    if first.is_ascii_digit() {
        let digits: String = code.chars().take_while(|c| c.is_ascii_digit()).collect();
        let v: u64 = digits.parse().ok()?;
        return (v > 0 && v <= i32::MAX as u64).then_some(v as i32);
    }
    let (mut value, mut offset, mut range) = (0u64, 0u64, 1u64);
    for c in code.chars() {
        if range > i32::MAX as u64 {
            return None;
        }
        offset += range;
        value *= 26;
        match c {
            'A'..='Z' => value += c as u64 - 'A' as u64,
            'a'..='z' => value += c as u64 - 'a' as u64,
            _ => return None,
        }
        range *= 26;
    }
    let v = offset + value;
    (v <= i32::MAX as u64).then_some(v as i32)
}

/// The code of variation number `v` in upper case (`Variation::toString`);
/// `None` for `v < 1`.
pub fn to_code(v: i32) -> Option<String> {
    if v < 1 {
        return None;
    }
    let (mut length, mut range, mut var) = (0usize, 1u64, v as u64);
    while var >= range && range < i32::MAX as u64 {
        length += 1;
        var -= range;
        range *= 26;
    }
    let mut out = vec![b'A'; length];
    for slot in out.iter_mut().rev() {
        let d = (var % 26) as u8;
        var /= 26;
        *slot = b'A' + d;
    }
    String::from_utf8(out).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_round_trip() {
        assert_eq!(from_code("A"), Some(1));
        assert_eq!(from_code("Z"), Some(26));
        assert_eq!(from_code("AA"), Some(27));
        assert_eq!(from_code("abc"), from_code("ABC"));
        assert_eq!(from_code("ABC"), Some(1 + 26 + 676 + 28));
        assert_eq!(from_code("12"), Some(12));
        assert_eq!(from_code("A-"), None);
        for v in [1, 26, 27, 702, 703, 731, 123_456] {
            assert_eq!(from_code(&to_code(v).unwrap()), Some(v));
        }
    }
}
