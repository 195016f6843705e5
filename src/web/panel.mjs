// panel.mjs - the settings panel, built from phyllo-export --settings as
// the Blender add-on's panel is: a box a group (the scene, the model,
// each organs entry, each part), a field a setting by its type (a menu
// for a word of a list, a slider beside a number with a range, the
// text of an expression, else the scene file's own syntax), its range,
// unit and man page line as its title, greyed out with the reason where
// the other settings leave it unused.  A change is a --set PATH=VALUE
// the page keeps (marked *, undone by its ↺); the program's message
// about one shows under its field.  Everything from a scene is text.

// The box a setting goes in: "Scene", "planar", "collision.receptacle",
// "Organs entry 1", and for a part "Achene: planar"...
export function groupOf(path) {
  const colon = path.indexOf(':');
  const part = colon >= 0 ? path.slice(0, colon) + ': ' : '';
  const parts = path.slice(colon + 1).split('.');
  if (parts.length === 1)
    return part + 'Scene';
  if (parts[0] === 'organs')
    return part + `Organs entry ${parts[1]}`;
  return part + parts.slice(0, -1).join('.');
}

// The field a setting gets, as the Blender panel's kind_of().
function kindOf(s) {
  if (s.choices)
    return 'choice';
  if ((s.type === 'number' || s.type === 'integer') && s.value !== null)
    return s.type;
  if (s.type === 'expression')
    return 'expression';
  return 'text';
}

// "[1, 10000000]", "(0, 4]": a setting's range.
export function interval(s) {
  if (s.min === undefined && s.max === undefined)
    return '';
  return `${s.min_open || s.min === undefined ? '(' : '['}` +
    `${s.min === undefined ? '-inf' : s.min}, ` +
    `${s.max === undefined ? 'inf' : s.max}]`;
}

const quoted = t => t.length >= 2 && t.startsWith('"') && t.endsWith('"');
const unquote = t => t.slice(1, -1).replace(/\\"/g, '"').replace(/\\\\/g, '\\');
const quote = t => '"' + t.replace(/\\/g, '\\\\').replace(/"/g, '\\"') + '"';

// What a field shows of a value in scene syntax, and back.
function shown(kind, value) {
  if (value === null || value === undefined)
    return '';
  return (kind === 'choice' || kind === 'expression') && quoted(value) ?
    unquote(value) : value;
}

function written(kind, text) {
  if (kind === 'choice')
    return text === '' ? '' : quote(text);
  if (kind === 'expression') {
    const t = text.trim();
    return t === '' ? '' : Number.isFinite(Number(t)) ? t : quote(text);
  }
  return text.trim();
}

function el(tag, props = {}, ...children) {
  const e = document.createElement(tag);
  Object.assign(e, props);
  e.append(...children);
  return e;
}

export class Panel {
  // onSet(path, value): a change (value in scene syntax) or, value
  // null, its undoing.
  constructor(container, last, onSet) {
    this.container = container;
    this.last = last;
    this.onSet = onSet;
    this.rows = new Map();
    this.order = '';
    this.open = new Map();	// group -> open, as the user left it
    this.lastPath = null;
  }

  /*
   * The panel for the settings of --settings (its "settings" list) and
   * the changes kept (a Map path -> value); rebuilt where the list of
   * settings changed (another model), else updated in place so that a
   * field being edited keeps its place.
   */
  build(settings, changes) {
    const order = settings.map(s => s.path).join('\n');
    if (order !== this.order) {
      this.order = order;
      this.make(settings);
    }
    for (const s of settings)
      this.update(this.rows.get(s.path), s, changes);
    this.showLast(settings, changes);
  }

  make(settings) {
    const focused = document.activeElement;
    const focusPath = focused && focused.dataset ? focused.dataset.path : null;
    this.rows.clear();
    const boxes = [];
    let box = null, group = null;
    for (const s of settings) {
      if (groupOf(s.path) !== group) {
        group = groupOf(s.path);
        const name = group, b = el('details', {
          open: this.open.has(name) ? this.open.get(name) :
            !/^Organs entry|: /.test(name) }, el('summary', { textContent: name }));
        b.addEventListener('toggle', () => this.open.set(name, b.open));
        box = b;
        boxes.push(box);
      }
      box.append(this.row(s));
    }
    this.container.replaceChildren(...boxes);
    if (focusPath && this.rows.has(focusPath))
      this.rows.get(focusPath).input.focus();
  }

  row(s) {
    const kind = kindOf(s);
    const r = { kind, path: s.path };
    r.label = el('span', { className: 'name' });
    if (kind === 'choice') {
      r.input = el('select');
    } else {
      r.input = el('input', { type: 'text', spellcheck: false });
      if (kind === 'number' && Number.isFinite(s.min) && Number.isFinite(s.max))
        r.range = el('input', { type: 'range', min: s.min, max: s.max,
          step: (s.max - s.min) / 1000 });
    }
    r.input.dataset.path = s.path;
    r.input.setAttribute('aria-label', s.path);
    r.reset = el('button', { type: 'button', className: 'reset',
      textContent: '↺', title: 'Undo the change' });
    r.why = el('div', { className: 'why' });
    r.error = el('div', { className: 'err' });
    const commit = text => {
      this.lastPath = s.path;
      this.onSet(s.path, written(kind, text));
    };
    r.input.addEventListener('change', () => commit(r.input.value));
    if (r.range) {
      r.range.addEventListener('input', () => {
        r.input.value = r.range.value;
        commit(r.range.value);
      });
    }
    r.reset.addEventListener('click', () => {
      this.lastPath = s.path;
      this.onSet(s.path, null);
    });
    r.row = el('div', { className: 'setting' },
      el('label', {}, r.label, r.input), ...(r.range ? [r.range] : []),
      r.reset, r.why, r.error);
    this.rows.set(s.path, r);
    return r.row;
  }

  update(r, s, changes) {
    const changed = changes.has(s.path);
    const value = changed ? changes.get(s.path) : s.value;
    r.label.textContent = s.path.replace(/^.*[:.]/, '') + (changed ? ' *' : '');
    r.row.title = [s.doc, interval(s) && `range ${interval(s)}`, s.unit,
      `default ${s.default}`].filter(Boolean).join('; ');
    if (r.kind === 'choice') {
      const words = (s.value === null && !changed ? [''] : []).concat(s.choices);
      if (r.input.options.length !== words.length ||
          [...r.input.options].some((o, i) => o.value !== words[i]))
        r.input.replaceChildren(...words.map(w =>
          el('option', { value: w, textContent: w === '' ? 'none' : w })));
    }
    if (document.activeElement !== r.input)
      r.input.value = shown(r.kind, value);
    if (r.range && document.activeElement !== r.range &&
        Number.isFinite(Number(value)))
      r.range.value = Number(value);
    const applies = s.applies !== false;
    r.row.classList.toggle('unused', !applies);
    r.input.disabled = !applies;
    if (r.range)
      r.range.disabled = !applies;
    r.why.textContent = applies ? '' : s.why || '';
    r.reset.hidden = !changed;
  }

  // The setting changed last, whole: what the rows leave out.
  showLast(settings, changes) {
    const s = settings.find(x => x.path === this.lastPath);
    if (s === undefined) {
      this.last.replaceChildren();
      this.last.hidden = true;
      return;
    }
    this.last.hidden = false;
    this.last.replaceChildren(el('b', { textContent: `${s.path}: ${s.type}` }),
      ' ' + [s.doc, interval(s) && `range ${interval(s)}`, s.unit,
        `default ${s.default}`, `file ${s.from === 'file' ? s.value : 'none'}`,
        changes.has(s.path) ? `changed to ${changes.get(s.path)}` : '']
        .filter(Boolean).join('; '));
  }

  // Messages about --set PATH=...: each under its field; those of a path
  // with no field returned, for the page to show.
  errors(messages) {
    for (const r of this.rows.values()) {
      r.error.textContent = '';
      r.error.className = 'warn';
    }
    const rest = [];
    for (const m of messages) {
      const r = m.set !== null ? this.rows.get(m.set) : undefined;
      if (r !== undefined) {
        r.error.textContent = r.error.textContent ? r.error.textContent + '\n' + m.text : m.text;
        if (!m.warning)
          r.error.className = 'err';
      } else if (m.set !== null) {
        rest.push(m);
      }
    }
    return rest;
  }
}
