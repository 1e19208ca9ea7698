// Types of the 'conecurl/engine' entry: the wasm engine's Embind module (engine/load-engine.d.ts).
export * from './engine/load-engine.js';
