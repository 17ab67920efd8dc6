//! The analysis's hash maps: the standard library's, with foldhash's hasher
//! in place of SipHash. Names and line numbers are looked up several times a
//! line, where SipHash took a twentieth of a hand-written program's check.
//! Its seed is drawn once a process, so a program cannot be written to make
//! its names collide (foldhash's "minimally DoS-resistant" hasher).

pub type HashMap<K, V> = std::collections::HashMap<K, V, foldhash::fast::RandomState>;
pub type HashSet<T> = std::collections::HashSet<T, foldhash::fast::RandomState>;
