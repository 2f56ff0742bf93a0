//! Seals over rapier's saved state: a 64-bit hash of each of rapier's sets, taken when a
//! snapshot is written and checked when it is restored.
//!
//! Rapier's sets hold private cross-references (each body's place in its island and in
//! the active set, the islands' lists of bodies, the broad phase's tree, the narrow
//! phase's contact graph) that no public method lets a restore check, and that rapier
//! indexes without checking. A snapshot whose rapier state differs in any bit from what
//! rapier wrote is refused rather than handed to rapier. The hash is a check against
//! damage (a value or an array changed by a disk, a transfer, an editor or another build
//! of rapier), not a signature: a snapshot crafted to match it is trusted as rapier's own.
//!
//! The hash feeds every value the set serialises, in serialisation order, through
//! `h = (h.rotl(5) ^ word) × K` with `K` odd: each step is a bijection of `h` for a given
//! word, so two serialisations that differ in one value always hash apart. Rapier's hash
//! sets, whose order is their buckets' and may change when they are read back, are sealed
//! as the sum of their items' seals, in any order.

use serde::ser::{self, Serialize};

/// Rapier's fields that are hash sets: their serialisation's order is the set's bucket
/// order, which a set read back with another capacity need not keep, so their items are
/// sealed in any order (the sum of each item's seal).
const UNORDERED: [&str; 2] = ["to_wake_up", "to_join"];

/// The hash of `value`'s serialisation ([`Sealer`]).
pub(crate) fn seal_of<T: Serialize + ?Sized>(value: &T) -> u64 {
    let mut sealer = Sealer {
        hash: 0x243f_6a88_85a3_08d3,
        sum: None,
    };
    // The sealer has no way to fail; a type's own serialiser may still refuse a value
    // (a map with keys it cannot write), which seals as that refusal.
    if value.serialize(&mut sealer).is_err() {
        sealer.word(u64::MAX);
    }
    sealer.hash
}

/// A serde serialiser that hashes what it is given.
pub(crate) struct Sealer {
    hash: u64,
    /// While an [`UNORDERED`] field's items are sealed: the sum of their seals.
    sum: Option<u64>,
}

/// The sealer never fails on its own; the error type serde needs.
#[derive(Debug)]
pub(crate) struct SealError;

impl std::fmt::Display for SealError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("a value refused to serialise")
    }
}

impl std::error::Error for SealError {}

impl ser::Error for SealError {
    fn custom<T: std::fmt::Display>(_: T) -> Self {
        SealError
    }
}

/// What kind of value the next words are, so that `[1, 2]`, `(1, 2)` and `1, 2` differ.
#[derive(Clone, Copy)]
enum Tag {
    Bool = 1,
    Int,
    Float,
    Text,
    None,
    Some,
    Unit,
    Variant,
    Seq,
    Map,
    Struct,
    End,
}

impl Sealer {
    fn word(&mut self, word: u64) {
        self.hash = (self.hash.rotate_left(5) ^ word).wrapping_mul(0x517c_c1b7_2722_0a95);
    }

    fn tag(&mut self, tag: Tag) {
        self.word(tag as u64);
    }

    fn bytes(&mut self, bytes: &[u8]) {
        self.tag(Tag::Text);
        self.word(bytes.len() as u64);
        for chunk in bytes.chunks(8) {
            let mut word = [0_u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            self.word(u64::from_le_bytes(word));
        }
    }

    fn int(&mut self, x: u64) -> Result<(), SealError> {
        self.tag(Tag::Int);
        self.word(x);
        Ok(())
    }
}

impl ser::Serializer for &mut Sealer {
    type Ok = ();
    type Error = SealError;
    type SerializeSeq = Self;
    type SerializeTuple = Self;
    type SerializeTupleStruct = Self;
    type SerializeTupleVariant = Self;
    type SerializeMap = Self;
    type SerializeStruct = Self;
    type SerializeStructVariant = Self;

    fn serialize_bool(self, v: bool) -> Result<(), SealError> {
        self.tag(Tag::Bool);
        self.word(u64::from(v));
        Ok(())
    }
    fn serialize_i8(self, v: i8) -> Result<(), SealError> {
        self.int(v as u64)
    }
    fn serialize_i16(self, v: i16) -> Result<(), SealError> {
        self.int(v as u64)
    }
    fn serialize_i32(self, v: i32) -> Result<(), SealError> {
        self.int(v as u64)
    }
    fn serialize_i64(self, v: i64) -> Result<(), SealError> {
        self.int(v as u64)
    }
    fn serialize_i128(self, v: i128) -> Result<(), SealError> {
        self.int(v as u64)?;
        self.int((v >> 64) as u64)
    }
    fn serialize_u8(self, v: u8) -> Result<(), SealError> {
        self.int(v.into())
    }
    fn serialize_u16(self, v: u16) -> Result<(), SealError> {
        self.int(v.into())
    }
    fn serialize_u32(self, v: u32) -> Result<(), SealError> {
        self.int(v.into())
    }
    fn serialize_u64(self, v: u64) -> Result<(), SealError> {
        self.int(v)
    }
    fn serialize_u128(self, v: u128) -> Result<(), SealError> {
        self.int(v as u64)?;
        self.int((v >> 64) as u64)
    }
    fn serialize_f32(self, v: f32) -> Result<(), SealError> {
        self.tag(Tag::Float);
        self.word(v.to_bits().into());
        Ok(())
    }
    fn serialize_f64(self, v: f64) -> Result<(), SealError> {
        self.tag(Tag::Float);
        self.word(v.to_bits());
        Ok(())
    }
    fn serialize_char(self, v: char) -> Result<(), SealError> {
        self.int(v.into())
    }
    fn serialize_str(self, v: &str) -> Result<(), SealError> {
        self.bytes(v.as_bytes());
        Ok(())
    }
    fn serialize_bytes(self, v: &[u8]) -> Result<(), SealError> {
        self.bytes(v);
        Ok(())
    }
    fn serialize_none(self) -> Result<(), SealError> {
        self.tag(Tag::None);
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<(), SealError> {
        self.tag(Tag::Some);
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), SealError> {
        self.tag(Tag::Unit);
        Ok(())
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<(), SealError> {
        self.serialize_unit()
    }
    fn serialize_unit_variant(
        self,
        _: &'static str,
        index: u32,
        _: &'static str,
    ) -> Result<(), SealError> {
        self.tag(Tag::Variant);
        self.word(index.into());
        Ok(())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        value: &T,
    ) -> Result<(), SealError> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        index: u32,
        _: &'static str,
        value: &T,
    ) -> Result<(), SealError> {
        self.serialize_unit_variant("", index, "")?;
        value.serialize(self)
    }
    fn serialize_seq(self, len: Option<usize>) -> Result<Self, SealError> {
        self.tag(Tag::Seq);
        // The count of items is hashed at the end (`End`), where it is always known.
        let _ = len;
        Ok(self)
    }
    fn serialize_tuple(self, len: usize) -> Result<Self, SealError> {
        self.serialize_seq(Some(len))
    }
    fn serialize_tuple_struct(self, _: &'static str, len: usize) -> Result<Self, SealError> {
        self.serialize_seq(Some(len))
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        index: u32,
        _: &'static str,
        len: usize,
    ) -> Result<Self, SealError> {
        self.serialize_unit_variant("", index, "")?;
        self.serialize_seq(Some(len))
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Self, SealError> {
        self.tag(Tag::Map);
        Ok(self)
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Self, SealError> {
        self.tag(Tag::Struct);
        Ok(self)
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        index: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self, SealError> {
        self.serialize_unit_variant("", index, "")?;
        self.serialize_struct("", 0)
    }
}

impl Sealer {
    fn item<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), SealError> {
        if let Some(sum) = self.sum.as_mut() {
            *sum = sum.wrapping_add(seal_of(value));
            return Ok(());
        }
        self.word(0x9e37_79b9_7f4a_7c15);
        value.serialize(self)
    }

    /// Seals a field's items in any order (an [`UNORDERED`] set's).
    fn unordered<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), SealError> {
        let mut items = Sealer {
            hash: 0,
            sum: Some(0),
        };
        value.serialize(&mut items)?;
        self.word(items.hash);
        self.word(items.sum.unwrap_or(0));
        Ok(())
    }

    fn end(&mut self) -> Result<(), SealError> {
        self.tag(Tag::End);
        Ok(())
    }
}

macro_rules! compound {
    ($($trait:ident: $method:ident),*) => {$(
        impl ser::$trait for &mut Sealer {
            type Ok = ();
            type Error = SealError;
            fn $method<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), SealError> {
                self.item(value)
            }
            fn end(self) -> Result<(), SealError> {
                Sealer::end(self)
            }
        }
    )*};
}

compound!(
    SerializeSeq: serialize_element,
    SerializeTuple: serialize_element,
    SerializeTupleStruct: serialize_field,
    SerializeTupleVariant: serialize_field
);

impl ser::SerializeMap for &mut Sealer {
    type Ok = ();
    type Error = SealError;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), SealError> {
        self.item(key)
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), SealError> {
        self.item(value)
    }
    fn end(self) -> Result<(), SealError> {
        Sealer::end(self)
    }
}

macro_rules! fields {
    ($($trait:ident),*) => {$(
        impl ser::$trait for &mut Sealer {
            type Ok = ();
            type Error = SealError;
            fn serialize_field<T: Serialize + ?Sized>(
                &mut self,
                key: &'static str,
                value: &T,
            ) -> Result<(), SealError> {
                self.bytes(key.as_bytes());
                if UNORDERED.contains(&key) {
                    self.unordered(value)
                } else {
                    self.item(value)
                }
            }
            fn skip_field(&mut self, key: &'static str) -> Result<(), SealError> {
                self.bytes(key.as_bytes());
                self.tag(Tag::None);
                Ok(())
            }
            fn end(self) -> Result<(), SealError> {
                Sealer::end(self)
            }
        }
    )*};
}

fields!(SerializeStruct, SerializeStructVariant);

#[cfg(test)]
mod tests {
    use super::seal_of;

    #[test]
    fn one_value_changed_anywhere_changes_the_seal() {
        let base: (Vec<f32>, Option<u32>, String) = (vec![1.0, 2.0, 3.0], Some(7), "ab".into());
        let seal = seal_of(&base);
        assert_eq!(
            seal,
            seal_of(&base.clone()),
            "the same value, the same seal"
        );
        let mut changed = Vec::new();
        for i in 0..3 {
            let mut v = base.clone();
            v.0[i] = f32::from_bits(v.0[i].to_bits() ^ 1);
            changed.push(v);
        }
        let mut v = base.clone();
        v.1 = None;
        changed.push(v);
        let mut v = base.clone();
        v.0.pop();
        changed.push(v);
        let mut v = base.clone();
        v.2.push('c');
        changed.push(v);
        for v in changed {
            assert_ne!(seal_of(&v), seal, "{v:?} seals as {base:?}");
        }
    }

    #[test]
    fn a_hash_set_field_seals_in_any_order() {
        #[derive(serde::Serialize)]
        struct Joints {
            to_join: Vec<(u32, u32)>,
            graph: Vec<u32>,
        }
        let a = Joints {
            to_join: vec![(1, 2), (3, 4)],
            graph: vec![5, 6],
        };
        let b = Joints {
            to_join: vec![(3, 4), (1, 2)],
            graph: vec![5, 6],
        };
        assert_eq!(seal_of(&a), seal_of(&b), "a set's items in another order");
        let c = Joints {
            to_join: vec![(3, 4), (1, 3)],
            graph: vec![5, 6],
        };
        assert_ne!(seal_of(&a), seal_of(&c), "a set's item changed");
        let d = Joints {
            to_join: vec![(1, 2), (3, 4)],
            graph: vec![6, 5],
        };
        assert_ne!(seal_of(&a), seal_of(&d), "other fields keep their order");
    }

    #[test]
    fn nesting_is_part_of_the_seal() {
        let flat: Vec<u32> = vec![1, 2, 3, 4];
        let nested: Vec<Vec<u32>> = vec![vec![1, 2], vec![3, 4]];
        let split: Vec<Vec<u32>> = vec![vec![1], vec![2, 3, 4]];
        assert_ne!(seal_of(&flat), seal_of(&nested));
        assert_ne!(seal_of(&nested), seal_of(&split));
    }
}
