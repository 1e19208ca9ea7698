// The 'conecurl/engine' entry: the wasm engine for tools that drive it from JavaScript (engine/load-engine.js).
export { loadEngine } from './engine/load-engine.js';
