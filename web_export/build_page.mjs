// Bundles the web page into one HTML template (issue 16):
//   node build_page.mjs NODE_MODULES GLUE_JS WASM_GZ OUTPUT
// page/main.js and its modules, three.js and KaTeX are bundled by esbuild
// into one script; page/style.css and KaTeX's CSS into one style sheet, with
// KaTeX's fonts as data: URLs (woff2 only: every browser that runs the page
// reads it); the wasm module (one JavaScript file, the wasm inside) goes in
// a script of its own, the wasm in a data block. Nothing is loaded from anywhere at run time: the
// page's Content-Security-Policy forbids it.
import { readFileSync, writeFileSync, renameSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const [modules, glueJs, wasmGz, output] = process.argv.slice(2);
if (!output) {
  console.error('usage: node build_page.mjs NODE_MODULES GLUE_JS WASM_GZ OUTPUT');
  process.exit(2);
}
const here = dirname(fileURLToPath(import.meta.url));
const require = createRequire(join(modules, 'noop.js'));
const esbuild = require('esbuild');

// KaTeX's @font-face rules name woff2, woff and ttf files: keep woff2.
const woff2Only = {
  name: 'katex-woff2-only',
  setup(build) {
    build.onLoad({ filter: /katex\.css$/ }, (args) => ({
      contents: readFileSync(args.path, 'utf8').replace(/,\s*url\([^)]*\.woff\) format\("woff"\)/g, '')
        .replace(/,\s*url\([^)]*\.ttf\) format\("truetype"\)/g, ''),
      loader: 'css',
    }));
  },
};

const common = { bundle: true, minify: true, write: false, logLevel: 'error', nodePaths: [modules], charset: 'ascii' }; // no raw bidi controls in promyk's C++ literal
const script = await esbuild.build({
  ...common,
  entryPoints: [join(here, 'page', 'main.js')],
  format: 'iife',
  target: ['chrome100', 'firefox100', 'safari15'],
  legalComments: 'none',
});
const style = await esbuild.build({
  ...common,
  entryPoints: [join(here, 'page', 'style.css')],
  loader: { '.woff2': 'dataurl', '.woff': 'dataurl', '.ttf': 'dataurl' },
  plugins: [woff2Only],
});

// A script's text ends at the first "</script": write it as "<\/script"
// (inside a JavaScript string or regular expression, the same text).
// "<!--" would let a later "<script" change how the HTML parser reads the rest.
const inline = (text) => {
  if (text.includes('<!--')) throw new Error('a script holds "<!--"');
  return text.replace(/<\/script/gi, '<\\/script');
};
const appJs = inline(script.outputFiles[0].text);
// The tracer as wasm.cmake splits it (wasm/split_module.mjs): the glue, whose
// inline wasm is emptied, and the wasm gzip-compressed. The wasm goes into a
// data block of its own (base64); the page inflates it and passes it as
// createPromyk({wasmBinary}), so the glue never fetches its data: URL (the
// CSP would refuse that, with a console error).
const wasm = inline(readFileSync(glueJs, 'utf8'));
const wasmBase64 = readFileSync(wasmGz).toString('base64');
const css = style.outputFiles[0].text.replace(/<\/style/gi, '<\\/style');
if (/url\((?!["']?data:)/.test(css)) throw new Error('the style sheet names a file that is not embedded');

const parts = readFileSync(join(here, 'page', 'index.html'), 'utf8');
const fill = (text, marker, value) => {
  const pieces = text.split(marker);
  if (pieces.length !== 2) throw new Error(`page/index.html must hold ${marker} exactly once`);
  return pieces[0] + value + pieces[1];
};
let html = fill(parts, '/*@PROMYK_CSS@*/', css);
html = fill(html, '/*@PROMYK_WASM@*/', wasm);
html = fill(html, '@PROMYK_WASM_BINARY@', wasmBase64);
html = fill(html, '/*@PROMYK_APP@*/', appJs);
if (html.split('@PROMYK_EXPORT_DATA@').length !== 2) throw new Error('the data marker must appear exactly once');
writeFileSync(output + '.tmp', html);
renameSync(output + '.tmp', output);
