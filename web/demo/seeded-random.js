// The demo's one seeded random generator (mulberry32): its drawn pages and its synthetic voice come
// out the same on every run and machine.

/** A function returning numbers in [0, 1), the same sequence for the same `seed`. */
export function mulberry32(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
