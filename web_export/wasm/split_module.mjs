// The single-file module (promyk.js, its wasm inline as base64: 12 MB) split
// for a page that must stay small: the wasm gzip-compressed (about 1.7 MB),
// and the JavaScript glue with its inline wasm emptied. The page inflates the
// wasm (DecompressionStream('gzip'), no network) and passes it as
// createPromyk({wasmBinary}); the glue then never reads its own copy.
//
//   node split_module.mjs promyk.js promyk.wasm.gz promyk_glue.js
import { readFileSync, writeFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';

const [input, wasmOut, glueOut] = process.argv.slice(2);
if (!glueOut) {
  console.error('usage: node split_module.mjs PROMYK_JS WASM_GZ_OUT GLUE_JS_OUT');
  process.exit(2);
}
const prefix = 'data:application/octet-stream;base64,';
const js = readFileSync(input, 'utf8');
// The glue names the prefix once as a constant; the module is the text
// after it that starts with "\0asm" in base64.
const start = js.indexOf(prefix + 'AGFzbQ');
if (start < 0 || js.indexOf(prefix + 'AGFzbQ', start + 1) >= 0) {
  console.error(`${input}: not one inline wasm (built without SINGLE_FILE?)`);
  process.exit(1);
}
let end = start + prefix.length;
while (end < js.length && /[A-Za-z0-9+/=]/.test(js[end])) ++end;
const wasm = Buffer.from(js.slice(start + prefix.length, end), 'base64');
if (wasm.readUInt32BE(0) !== 0x0061736d) {
  console.error(`${input}: the inline data is not a wasm module`);
  process.exit(1);
}
writeFileSync(wasmOut, gzipSync(wasm, { level: 9 }));
writeFileSync(glueOut, js.slice(0, start + prefix.length) + js.slice(end));
