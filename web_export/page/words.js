// The page's words: every text comes from lessons/messages*.json through the
// tracer (promyk_messages), the same texts the command line prints.
let messages = {};

export function setMessages(table) {
  messages = table || {};
}

// The message `id` with its {placeholders} filled in.
export function t(id, args = {}) {
  const text = messages[id];
  if (typeof text !== 'string') return id;
  return text.replace(/\{([a-z_]+)\}/g, (whole, name) => (name in args ? String(args[name]) : whole));
}
