// The tracer: promyk's C++ compiled to WebAssembly (web_export/wasm/API.md).
// Every call returns a JSON text; a failure is {"error", "code"}, thrown here
// as a TracerError. Text arguments are copied into the module's heap (a
// scene may be 1 MiB, more than ccall's stack copy should carry).

export class TracerError extends Error {
  // details: the whole error object (a scene's "faults", "where", "file").
  constructor(message, code, details = {}) {
    super(message);
    this.code = code;
    this.details = details;
  }

  // The loader's faults as [{where, what}]: a scene's list, or the one
  // fault of an input error ("file: where: what" without the prefix).
  faults() {
    const d = this.details;
    if (Array.isArray(d.faults) && d.faults.length) return d.faults.map((f) => ({ where: String(f.where), what: String(f.what) }));
    const prefix = `${d.file ? `${d.file}: ` : ''}${d.where ? `${d.where}: ` : ''}`;
    const what = prefix && this.message.startsWith(prefix) ? this.message.slice(prefix.length) : this.message;
    return [{ where: typeof d.where === 'string' ? d.where : '', what }];
  }
}

export function makeTracer(M) {
  const withText = (text, use) => {
    const size = M.lengthBytesUTF8(text) + 1;
    const at = M._malloc(size);
    try {
      M.stringToUTF8(text, at, size);
      return use(at, size - 1);
    } finally {
      M._free(at);
    }
  };
  const checked = (text) => {
    const value = JSON.parse(text);
    if (value && typeof value === 'object' && 'error' in value) throw new TracerError(String(value.error), value.code, value);
    return value;
  };
  const callText = (name, texts, numbers = []) => {
    const go = (pointers) =>
      M.ccall(name, 'string', [...numbers.map(() => 'number'), ...pointers.map(() => 'number')],
        [...numbers, ...pointers]);
    const nest = (k, pointers) => (k === texts.length ? go(pointers) : withText(texts[k], (at) => nest(k + 1, [...pointers, at])));
    return nest(0, []);
  };
  return {
    version: () => checked(M.ccall('promyk_version', 'string', [], [])),
    openScene: (sceneText, sceneFile, w) =>
      checked(withText(sceneText, (a) => withText(sceneFile, (b) =>
        M.ccall('promyk_open_scene', 'string', ['number', 'number', 'number'], [a, b, w])))),
    // The trace's own text (what `promyk trace --format json` prints).
    trace(i, j, settings) {
      const text = callText('promyk_trace', [JSON.stringify(settings)], [i, j]);
      checked(text);
      return text;
    },
    view: (traceText, view) => checked(callText('promyk_view', [traceText, JSON.stringify(view)])),
    compare: (a, b, view) => checked(callText('promyk_compare', [a, b, JSON.stringify(view)])),
    openTraces(bytes) {
      const at = M._malloc(bytes.length + 1);
      try {
        M.HEAPU8.set(bytes, at);
        M.HEAPU8[at + bytes.length] = 0;
        return checked(M.ccall('promyk_open_traces', 'string', ['number', 'number'], [at, bytes.length]));
      } finally {
        M._free(at);
      }
    },
    traceFromFile(i, j) {
      const text = M.ccall('promyk_trace_from_file', 'string', ['number', 'number'], [i, j]);
      checked(text);
      return text;
    },
    legend: (lang) => checked(callText('promyk_legend', [lang])),
    // The loader's messages are worded in the language of the last call
    // that named one (API.md); the legend is the cheapest such call.
    useLanguage(lang) {
      checked(callText('promyk_legend', [lang]));
    },
    messages: (lang) => checked(callText('promyk_messages', [lang])),
    // The lessons of a language, and one lesson run by the C++ lesson runner as HTML.
    lessons: (lang) => checked(callText('promyk_lessons', [lang])),
    lesson: (name, options) => checked(callText('promyk_lesson', [name, JSON.stringify(options)])),
    // A worksheet's answer file from the typed texts ({blank: text}), and a file checked (worksheet.js).
    worksheetFile: (name, options, typed) =>
      checked(callText('promyk_worksheet_file', [name, JSON.stringify(options), JSON.stringify(typed)])),
    checkAnswers: (name, options, text) => checked(callText('promyk_check_answers', [name, JSON.stringify(options), text])),
  };
}
