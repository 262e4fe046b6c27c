// Times the WebAssembly ball pit in headless Chromium (Debian's, through the end-to-end
// test's playwright-core: run `npm ci` in web/e2e first), as run.mjs does in Node:
//   node chromium.mjs [balls] [seconds]
// CHROMIUM_FLAGS adds command-line flags (e.g. "--js-flags=--wasm-enforce-bounds-checks").
// The module is instantiated inside the page, with run.mjs's stubs for the imports the pit
// never calls (a function sent into the page cannot import them from a shared file).
import { readFile } from "node:fs/promises";
import { chromium } from "../../web/e2e/node_modules/playwright-core/index.mjs";
const [balls = 1000, seconds = 1] = process.argv.slice(2).map(Number);
const bytes = await readFile(new URL("./target/wasm32-unknown-unknown/release/newtonlab_wasm_bench.wasm", import.meta.url));
const browser = await chromium.launch({ executablePath: "/usr/bin/chromium", args: ["--no-sandbox", ...(process.env.CHROMIUM_FLAGS ? process.env.CHROMIUM_FLAGS.split(" ") : [])] });
try {
  const page = await browser.newPage();
  const version = browser.version();
  const result = await page.evaluate(async ({ base64, balls, steps }) => {
    const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
    const module = await WebAssembly.compile(bytes);
    const imports = {};
    for (const { module: from, name } of WebAssembly.Module.imports(module)) {
      imports[from] ??= {};
      imports[from][name] = () => { throw new Error(`the pit called ${from}.${name}`); };
    }
    const instance = await WebAssembly.instantiate(module, imports);
    const { build_pit, run_pit } = instance.exports;
    if (build_pit(balls) !== 0) throw new Error("the pit did not build");
    const start = performance.now();
    const reached = run_pit(steps);
    return { reached, elapsed: (performance.now() - start) / 1000 };
  }, { base64: bytes.toString("base64"), balls, steps: Math.round(seconds * 1000) });
  const steps = Math.round(seconds * 1000);
  console.log(`${balls}-ball pit in WebAssembly (Chromium ${version}), 0 to ${result.reached.toFixed(2)} s: ${(steps / result.elapsed).toFixed(1)} steps per second`);
} finally {
  await browser.close();
}
