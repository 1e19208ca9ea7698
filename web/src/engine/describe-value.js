// How every error message of conecurl shows a value it was given: one rule for all the layers' checks
// (options, methods, the document features), kept at the bottom layer so that each can import it.

/**
 * A value as an error message shows it: short, never the value's own toString (which may throw or
 * be huge), strings quoted so an empty one is visible.
 */
export function describeValue(value) {
  if (typeof value === 'string') return JSON.stringify(value.length > 60 ? `${value.slice(0, 57)}...` : value);
  if (typeof value === 'number' || typeof value === 'boolean' || value === null || value === undefined) return String(value);
  if (typeof value === 'bigint') return `${value}n`;
  if (typeof value === 'symbol') return 'a symbol';
  if (typeof value === 'function') return 'a function';
  if (Array.isArray(value)) return `an array of ${value.length}`;
  const name = Object.getPrototypeOf(value)?.constructor?.name;
  return name && name !== 'Object' ? `a ${name}` : 'an object';
}
