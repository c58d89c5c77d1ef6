// Performance measures of the page's phases (an edit's loader run, the
// workers, showing the image, the trace, the derivation, the 3D view), read
// by the browser test (tests/web/edit_test.mjs) to see where an edit's time
// goes. Named "promyk:PHASE" in the page's performance timeline.
export function timed(phase, work) {
  const start = performance.now();
  try {
    return work();
  } finally {
    performance.measure(`promyk:${phase}`, { start, end: performance.now() });
  }
}

export function measureSince(phase, start) {
  performance.measure(`promyk:${phase}`, { start, end: performance.now() });
}
