// editor.mjs - the scene's text (and its parts' and templates'): a
// textarea beside a gutter of line numbers, the lines a message names
// marked, and the program's messages below it, each taking you to its
// line and column.  Everything from a scene is written as text.

const PROGRAM = 'phyllo-export: ';

/*
 * One line of the program's standard error as { file, line, col, set,
 * warning, text }: "phyllo-export: FILE:LINE[:COL]: message", "...:
 * --set PATH=VALUE: message", "...: FILE: message", or a bare message.
 */
export function parseMessage(text) {
  const m = { file: null, line: 0, col: 0, set: null, warning: false, text };
  if (!text.startsWith(PROGRAM))
    return m;
  let rest = text.slice(PROGRAM.length);
  let at;
  if ((at = /^--set ([^=]*)=.*?: /.exec(rest)) !== null) {
    m.set = at[1];
  } else if ((at = /^([^:\n]+):(\d+)(?::(\d+))?: /.exec(rest)) !== null) {
    m.file = at[1];
    m.line = Number(at[2]);
    m.col = Number(at[3] || 0);
  } else if ((at = /^([^:\n]+\.[A-Za-z]+): /.exec(rest)) !== null) {
    m.file = at[1];
  }
  if (at !== null)
    rest = rest.slice(at[0].length);
  m.warning = rest.startsWith('warning: ');
  return m;
}

export class Editor {
  constructor({ select, gutter, text, messages }, onEdit) {
    this.select = select;
    this.gutter = gutter;
    this.text = text;
    this.list = messages;
    this.onEdit = onEdit;
    this.path = null;
    this.messages = [];
    this.lines = -1;
    text.addEventListener('input', () => {
      this.numbers();
      this.onEdit(this.path, text.value);
    });
    text.addEventListener('scroll', () => {
      gutter.scrollTop = text.scrollTop;
    });
    // Tab indents, as in a code editor, rather than leaving the text.
    text.addEventListener('keydown', e => {
      if (e.key !== 'Tab' || e.ctrlKey || e.altKey || e.metaKey)
        return;
      e.preventDefault();
      document.execCommand('insertText', false, '\t');
    });
    select.addEventListener('change', () => this.onSwitch(select.value));
    this.onSwitch = () => {};
  }

  // The text files one can edit, path shown first.
  setFiles(paths, shown) {
    this.select.replaceChildren(...paths.map(p => {
      const o = document.createElement('option');
      o.value = p;
      o.textContent = p;
      return o;
    }));
    this.select.value = shown;
  }

  show(path, text) {
    this.path = path;
    this.select.value = path;
    if (this.text.value !== text)
      this.text.value = text;
    this.lines = -1;
    this.numbers();
  }

  // The gutter: a number a line, the lines messages name marked.
  numbers() {
    const n = this.text.value.split('\n').length;
    const marks = new Map();
    for (const m of this.messages)
      if (m.file === this.path && m.line > 0 && !marks.has(m.line))
        marks.set(m.line, m);
    const key = n + ':' + [...marks.keys()].join(',');
    if (key === this.lines)
      return;
    this.lines = key;
    const frag = document.createDocumentFragment();
    for (let i = 1; i <= n; i++) {
      const span = document.createElement('span');
      span.textContent = i + '\n';
      const m = marks.get(i);
      if (m !== undefined) {
        span.className = m.warning ? 'warn' : 'err';
        span.title = m.text;
      }
      frag.append(span);
    }
    this.gutter.replaceChildren(frag);
    this.gutter.scrollTop = this.text.scrollTop;
  }

  // The program's messages (lines of its stderr), below the text.
  setMessages(lines) {
    this.messages = lines.filter(l => l !== '').map(parseMessage);
    this.list.replaceChildren(...this.messages.map(m => {
      const li = document.createElement('li');
      li.textContent = m.text;
      li.className = m.warning ? 'warn' : 'err';
      if (m.file !== null && m.line > 0) {
        li.tabIndex = 0;
        li.title = 'Go to the line';
        const go = () => this.goTo(m.file, m.line, m.col);
        li.addEventListener('click', go);
        li.addEventListener('keydown', e => { if (e.key === 'Enter') go(); });
      }
      return li;
    }));
    this.lines = -1;
    this.numbers();
  }

  // Select line (and column) of file, switching to it if it is another.
  goTo(file, line, col) {
    if (file !== this.path) {
      if (![...this.select.options].some(o => o.value === file))
        return;
      this.onSwitch(file);
    }
    const lines = this.text.value.split('\n');
    let start = 0;
    for (let i = 0; i < line - 1 && i < lines.length; i++)
      start += lines[i].length + 1;
    const here = lines[line - 1] || '';
    const from = start + Math.max(0, Math.min(here.length, col - 1));
    const to = col > 0 ? from + Math.max(1, (/^\w+/.exec(here.slice(col - 1)) || [''])[0].length) :
      start + here.length;
    this.text.focus();
    this.text.setSelectionRange(col > 0 ? from : start, Math.min(to, start + here.length));
    const height = this.text.scrollHeight / Math.max(1, lines.length);
    this.text.scrollTop = Math.max(0, (line - 4) * height);
  }
}
