// Times the WebAssembly ball pit in Node (V8, the engine of Chromium):
//   node run.mjs [balls] [seconds]
import { readFile } from "node:fs/promises";
const [balls = 1000, seconds = 1] = process.argv.slice(2).map(Number);
const bytes = await readFile(new URL("./target/wasm32-unknown-unknown/release/newtonlab_wasm_bench.wasm", import.meta.url));
// The physics links wasm-bindgen (through the locale lookup of its messages), whose
// imports the pit never calls: each is a stub that says so if it ever is.
const module = await WebAssembly.compile(bytes);
const imports = {};
for (const { module: from, name } of WebAssembly.Module.imports(module)) {
  imports[from] ??= {};
  imports[from][name] = () => { throw new Error(`the pit called ${from}.${name}`); };
}
const instance = await WebAssembly.instantiate(module, imports);
const { build_pit, run_pit } = instance.exports;
if (build_pit(balls) !== 0) throw new Error("the pit did not build");
const steps = Math.round(seconds * 1000);
const start = performance.now();
const reached = run_pit(steps);
const elapsed = (performance.now() - start) / 1000;
console.log(`${balls}-ball pit in WebAssembly (Node ${process.version}), 0 to ${reached.toFixed(2)} s: ${(steps / elapsed).toFixed(1)} steps per second`);
