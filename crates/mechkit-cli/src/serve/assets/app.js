// mechkit serve: the app's script (plain JavaScript, no framework, nothing from the network).
// The scenario list (GET /api/files), the editor checked as one types (POST /api/check,
// 300 ms after the last key), a run (POST /api/run, then GET /api/run/ID until it ends) and
// its plots, animation and files.
(function () {
  'use strict';

  var CHECK_DELAY_MS = 300;
  var POLL_MS = 250;

  var $ = function (id) {
    return document.getElementById(id);
  };
  var editor = $('editor');
  var gutterLines = $('gutter-lines');
  var marks = $('marks');
  var errorsList = $('errors');
  var runButton = $('run');
  var stopButton = $('stop');

  var state = {
    name: '', // the scenario's path in the workspace, or gallery:STEM.toml
    original: '', // its text as opened
    errors: [], // the last check's errors
    checkSeq: 0, // the number of the last check asked for
    checkTimer: null,
    valid: false,
    runId: null,
    lines: 0
  };

  // ---------- requests

  function api(path, options) {
    return fetch(path, options).then(function (response) {
      return response.json().catch(function () {
        return {error: response.status + ' ' + response.statusText};
      }).then(function (body) {
        if (!response.ok) {
          var e = new Error(body.error || response.statusText);
          e.status = response.status;
          throw e;
        }
        return body;
      });
    });
  }

  function post(path, body) {
    return api(path, {
      method: 'POST',
      headers: {'Content-Type': 'application/json'},
      body: JSON.stringify(body)
    });
  }

  function el(tag, className, text) {
    var node = document.createElement(tag);
    if (className) {
      node.className = className;
    }
    if (text !== undefined) {
      node.textContent = text;
    }
    return node;
  }

  function setBadge(node, text, kind) {
    node.textContent = text;
    node.className = 'badge' + (kind ? ' ' + kind : '');
  }

  function bytes(n) {
    if (n < 1000) {
      return n + ' B';
    }
    var units = ['kB', 'MB', 'GB'];
    var i = -1;
    do {
      n /= 1000;
      i += 1;
    } while (n >= 1000 && i < units.length - 1);
    return n.toFixed(n < 10 ? 1 : 0) + ' ' + units[i];
  }

  function number(x) {
    if (typeof x !== 'number' || !isFinite(x)) {
      return String(x);
    }
    if (x === 0) {
      return '0';
    }
    var a = Math.abs(x);
    return a >= 1e5 || a < 1e-3 ? x.toExponential(3) : String(+x.toPrecision(5));
  }

  // ---------- the scenario list

  function loadFiles() {
    return api('/api/files').then(function (list) {
      $('workspace').textContent = list.workspace;
      var files = $('files');
      files.textContent = '';
      list.files.forEach(function (f) {
        var li = el('li');
        var slash = f.path.lastIndexOf('/');
        if (slash >= 0) {
          li.appendChild(el('span', 'dir', f.path.slice(0, slash + 1)));
        }
        li.appendChild(document.createTextNode(f.path.slice(slash + 1)));
        li.dataset.path = f.path;
        li.title = f.path + ' (' + bytes(f.bytes) + ')';
        files.appendChild(li);
      });
      if (!list.files.length) {
        files.appendChild(el('li', 'none', 'no *.toml files'));
      }
      $('files-count').textContent = list.files.length + (list.truncated ? '+' : '');
      var gallery = $('gallery');
      gallery.textContent = '';
      var openable = 0;
      list.gallery.forEach(function (c) {
        c.scenarios.forEach(function (s) {
          var li = el('li');
          li.appendChild(document.createTextNode(s.slice('gallery:'.length).replace(/\.toml$/, '')));
          li.appendChild(el('span', 'topic', c.topic));
          li.dataset.path = s;
          li.title = c.asked;
          gallery.appendChild(li);
          openable += 1;
        });
      });
      $('gallery-count').textContent = openable ? openable : '';
      markActive();
    }).catch(function (e) {
      $('files').textContent = '';
      $('files').appendChild(el('li', 'none', 'cannot list the files: ' + e.message));
    });
  }

  function markActive() {
    document.querySelectorAll('.files li').forEach(function (li) {
      li.classList.toggle('active', li.dataset.path === state.name);
    });
  }

  function filter() {
    var words = $('filter').value.toLowerCase().split(/\s+/).filter(Boolean);
    document.querySelectorAll('.files li[data-path]').forEach(function (li) {
      var text = li.textContent.toLowerCase();
      li.hidden = !words.every(function (w) {
        return text.indexOf(w) >= 0;
      });
    });
  }

  function openFile(path) {
    return api('/api/file?path=' + encodeURIComponent(path)).then(function (file) {
      state.name = file.path;
      state.original = file.text;
      editor.value = file.text;
      editor.scrollTop = 0;
      editor.scrollLeft = 0;
      $('file-name').textContent = file.path.replace(/^gallery:/, 'gallery / ');
      $('file-name').title = file.path;
      if (location.hash.slice(1) !== encodeURIComponent(file.path)) {
        history.replaceState(null, '', '#' + encodeURIComponent(file.path));
      }
      markActive();
      edited();
      check();
    }).catch(function (e) {
      showErrors([{line: null, column: null, message: 'cannot open ' + path + ': ' + e.message}]);
    });
  }

  // ---------- the editor

  function renderGutter() {
    var count = editor.value.split('\n').length;
    if (count !== state.lines) {
      var fragment = document.createDocumentFragment();
      for (var i = 1; i <= count; i += 1) {
        var row = el('div', '', String(i));
        row.dataset.line = i;
        fragment.appendChild(row);
      }
      gutterLines.textContent = '';
      gutterLines.appendChild(fragment);
      state.lines = count;
    }
    var bad = {};
    state.errors.forEach(function (e) {
      if (e.line) {
        bad[e.line] = true;
      }
    });
    Array.prototype.forEach.call(gutterLines.children, function (row) {
      row.className = bad[row.dataset.line] ? 'error' : '';
    });
    renderMarks();
  }

  function metrics() {
    var style = getComputedStyle(editor);
    var probe = el('span', '', 'MMMMMMMMMM');
    probe.style.font = style.font;
    probe.style.visibility = 'hidden';
    probe.style.position = 'absolute';
    document.body.appendChild(probe);
    var ch = probe.getBoundingClientRect().width / 10;
    probe.remove();
    return {
      ch: ch,
      row: parseFloat(style.lineHeight) || 20,
      top: parseFloat(style.paddingTop) || 0,
      left: parseFloat(style.paddingLeft) || 0
    };
  }

  function renderMarks() {
    marks.textContent = '';
    if (!state.errors.length) {
      return;
    }
    var m = metrics();
    state.errors.forEach(function (e) {
      if (!e.line) {
        return;
      }
      var top = m.top + (e.line - 1) * m.row - editor.scrollTop;
      var band = el('div', 'band');
      band.style.top = top + 'px';
      marks.appendChild(band);
      var squiggle = el('div', 'squiggle');
      squiggle.style.top = (top + m.row - 3) + 'px';
      squiggle.style.left = (m.left + (e.column - 1) * m.ch - editor.scrollLeft) + 'px';
      squiggle.style.width = Math.max(1, e.width || 1) * m.ch + 'px';
      marks.appendChild(squiggle);
    });
  }

  function syncScroll() {
    gutterLines.style.transform = 'translateY(' + -editor.scrollTop + 'px)';
    renderMarks();
  }

  function edited() {
    $('edited').hidden = editor.value === state.original;
    renderGutter();
  }

  function scheduleCheck() {
    clearTimeout(state.checkTimer);
    state.checkTimer = setTimeout(check, CHECK_DELAY_MS);
  }

  function check() {
    clearTimeout(state.checkTimer);
    if (!editor.value.trim()) {
      state.valid = false;
      showErrors([]);
      setBadge($('status'), '', '');
      $('status').title = '';
      updateRunButton();
      return;
    }
    var seq = ++state.checkSeq;
    setBadge($('status'), 'checking', 'busy');
    post('/api/check', {name: state.name, text: editor.value}).then(function (checked) {
      if (seq !== state.checkSeq) {
        return; // the text has changed since: a newer check is coming
      }
      state.valid = checked.ok;
      showErrors(checked.errors, checked.warnings);
      if (checked.ok) {
        var r = checked.report;
        setBadge($('status'), 'valid', 'ok');
        $('status').title = r.dimensions + '-D, ' + r.bodies.map(function (b) {
          return b.name;
        }).join(', ') + '; ' + r.method;
      } else {
        var n = checked.errors.length;
        setBadge($('status'), n + (n === 1 ? ' error' : ' errors'), 'bad');
        $('status').title = '';
      }
      updateRunButton();
    }).catch(function (e) {
      if (seq === state.checkSeq) {
        state.valid = false;
        showErrors([{line: null, column: null, message: e.message}]);
        setBadge($('status'), 'not checked', 'bad');
        updateRunButton();
      }
    });
  }

  function showErrors(errors, warnings) {
    state.errors = errors || [];
    errorsList.textContent = '';
    state.errors.forEach(function (e) {
      var li = el('li');
      if (e.line) {
        li.dataset.line = e.line;
        li.dataset.column = e.column;
        li.appendChild(el('span', 'loc', e.line + ':' + e.column));
      }
      li.appendChild(document.createTextNode(e.message));
      if (e.hint) {
        li.appendChild(el('span', 'hint', 'hint: ' + e.hint));
      }
      li.addEventListener('click', function () {
        if (e.line) {
          goTo(e.line, e.column);
        }
      });
      errorsList.appendChild(li);
    });
    (warnings || []).forEach(function (w) {
      errorsList.appendChild(el('li', 'warning', 'warning: ' + w));
    });
    renderGutter();
  }

  function goTo(line, column) {
    var lines = editor.value.split('\n');
    var offset = 0;
    for (var i = 0; i < line - 1 && i < lines.length; i += 1) {
      offset += lines[i].length + 1;
    }
    offset += Math.max(0, (column || 1) - 1);
    editor.focus();
    editor.setSelectionRange(offset, offset);
    var m = metrics();
    var top = (line - 1) * m.row;
    if (top < editor.scrollTop || top > editor.scrollTop + editor.clientHeight - 3 * m.row) {
      editor.scrollTop = Math.max(0, top - editor.clientHeight / 3);
    }
  }

  function onKey(event) {
    if (event.key === 'Enter' && (event.ctrlKey || event.metaKey)) {
      event.preventDefault();
      if (!runButton.disabled) {
        run();
      }
    } else if (event.key === 'Tab' && !event.shiftKey) {
      event.preventDefault();
      var start = editor.selectionStart;
      editor.setRangeText('  ', start, editor.selectionEnd, 'end');
      editor.dispatchEvent(new Event('input'));
    }
  }

  function save() {
    var blob = new Blob([editor.value], {type: 'application/toml'});
    var link = el('a');
    link.href = URL.createObjectURL(blob);
    var base = (state.name || 'scenario.toml').replace(/^gallery:/, '');
    link.download = base.slice(base.lastIndexOf('/') + 1);
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(function () {
      URL.revokeObjectURL(link.href);
    }, 1000);
  }

  // ---------- a run

  function updateRunButton() {
    runButton.disabled = state.runId !== null || !state.valid;
  }

  function run() {
    clearResult();
    $('placeholder').hidden = true;
    setBadge($('run-state'), 'starting', 'busy');
    $('result-title').textContent = $('file-name').textContent;
    post('/api/run', {name: state.name, text: editor.value}).then(function (started) {
      state.runId = started.id;
      updateRunButton();
      stopButton.hidden = false;
      $('progress-row').hidden = false;
      progress(0, '');
      poll(started.id);
    }).catch(function (e) {
      setBadge($('run-state'), e.status === 429 ? 'busy' : 'not started', 'bad');
      message(e.message, true);
    });
  }

  function poll(id) {
    api('/api/run/' + id).then(function (view) {
      if (view.state === 'running') {
        var t = view.t !== null && view.t !== undefined ? 't = ' + number(view.t) + ' s' : '';
        var of = view.t_max ? ' of ' + number(view.t_max) + ' s' : '';
        progress(view.progress, t + of);
        setBadge($('run-state'), 'running ' + view.seconds.toFixed(1) + ' s', 'busy');
        setTimeout(function () {
          poll(id);
        }, POLL_MS);
      } else {
        progress(1, 'done in ' + view.seconds.toFixed(1) + ' s');
        finish(view);
      }
    }).catch(function (e) {
      finish({state: 'failed', error: e.message, plots: [], files: []});
    });
  }

  function progress(fraction, text) {
    $('progress').style.width = (100 * Math.max(0, Math.min(1, fraction))) + '%';
    $('progress-text').textContent = text;
  }

  function stop() {
    if (state.runId !== null) {
      post('/api/run/' + state.runId + '/stop', {}).catch(function () {});
    }
  }

  function clearResult() {
    $('run-message').hidden = true;
    $('summary').textContent = '';
    $('plots').textContent = '';
    $('downloads').textContent = '';
    $('downloads-box').hidden = true;
    var frame = $('animation');
    frame.hidden = true;
    frame.removeAttribute('src');
  }

  function message(text, isError) {
    var box = $('run-message');
    box.textContent = text;
    box.className = 'message' + (isError ? ' error' : '');
    box.hidden = false;
  }

  function finish(view) {
    state.runId = null;
    stopButton.hidden = true;
    updateRunButton();
    setBadge($('run-state'), view.state === 'done' ? 'done' : 'stopped early', view.state === 'done' ? 'ok' : 'bad');
    if (view.error) {
      message(view.error, !view.summary);
    }
    var s = view.summary;
    if (s) {
      showSummary(s);
      if (s.warnings && s.warnings.length) {
        message((view.error ? view.error + '\n' : '') + s.warnings.map(function (w) {
          return 'warning: ' + w;
        }).join('\n'), false);
      }
    }
    if (view.animation) {
      var frame = $('animation');
      frame.hidden = false;
      frame.src = view.animation;
    }
    var plots = $('plots');
    view.plots.forEach(function (p) {
      var figure = el('figure');
      var link = el('a');
      link.href = p.url;
      link.target = '_blank';
      var img = el('img');
      img.src = p.url;
      img.alt = p.name;
      link.appendChild(img);
      figure.appendChild(link);
      figure.appendChild(el('figcaption', '', p.name));
      plots.appendChild(figure);
    });
    showFiles(view);
  }

  // the files of a run; those still being drawn (the GIF) are shown as such and listed again
  // once written
  function showFiles(view) {
    var downloads = $('downloads');
    downloads.textContent = '';
    view.files.forEach(function (f) {
      var li = el('li');
      var a = el('a', '', f.name);
      a.href = f.url;
      a.download = f.name;
      a.appendChild(el('span', 'size', bytes(f.bytes)));
      li.appendChild(a);
      downloads.appendChild(li);
    });
    (view.pending || []).forEach(function (name) {
      var li = el('li', 'pending', name);
      li.appendChild(el('span', 'size', 'drawing\u2026'));
      downloads.appendChild(li);
    });
    $('downloads-box').hidden = !view.files.length;
    if (view.pending && view.pending.length && view.id !== undefined) {
      setTimeout(function () {
        api('/api/run/' + view.id).then(function (later) {
          if ($('downloads').dataset.run === String(view.id)) {
            showFiles(later);
          }
        }).catch(function () {});
      }, 1000);
    }
    downloads.dataset.run = String(view.id);
  }

  function showSummary(s) {
    var rows = [
      ['stop', s.stop_reason],
      ['t end', number(s.t_end) + ' s'],
      ['steps', String(s.steps)],
      ['method', s.method]
    ];
    if (typeof s.work_energy_residual === 'number') {
      rows.push(['W \u2212 \u0394K', number(s.work_energy_residual) + ' J']);
    }
    Object.keys(s.observables || {}).forEach(function (name) {
      rows.push([name, number(s.observables[name])]);
    });
    var box = $('summary');
    rows.forEach(function (r) {
      var item = el('div');
      item.appendChild(el('dt', '', r[0]));
      var dd = el('dd', '', r[1]);
      dd.title = r[1];
      item.appendChild(dd);
      box.appendChild(item);
    });
  }

  function fitAnimation() {
    var frame = $('animation');
    try {
      var doc = frame.contentDocument;
      var player = doc && doc.querySelector('.player');
      if (player) {
        // the player's picture scales with the frame's width: the body's padding around it
        frame.style.height = Math.ceil(player.getBoundingClientRect().height + 34) + 'px';
      }
    } catch (e) {
      // not loaded yet
    }
  }

  // ---------- wiring

  document.querySelectorAll('.files').forEach(function (list) {
    list.addEventListener('click', function (event) {
      var li = event.target.closest('li[data-path]');
      if (li) {
        openFile(li.dataset.path);
      }
    });
  });
  $('filter').addEventListener('input', filter);
  editor.addEventListener('input', function () {
    edited();
    state.valid = false;
    updateRunButton();
    scheduleCheck();
  });
  editor.addEventListener('scroll', syncScroll);
  editor.addEventListener('keydown', onKey);
  runButton.addEventListener('click', run);
  stopButton.addEventListener('click', stop);
  $('save').addEventListener('click', save);
  $('animation').addEventListener('load', fitAnimation);
  window.addEventListener('resize', function () {
    fitAnimation();
    renderMarks();
  });

  renderGutter();
  loadFiles().then(function () {
    var wanted = decodeURIComponent(location.hash.slice(1));
    if (wanted) {
      openFile(wanted);
    }
  });
})();
