/* crosscheck report: sorts and filters the summary table (status, name, only unexpected, only
   changed against a baseline), opens
   scene sections, zoom, flicker, onion skin and wipe, the pixel value readout, copying the
   expectations lines, and the self-check that index.html?check runs (used by the Chromium test).
   Embedded inline into index.html by report.cpp. No network and no libraries: the readout's pixel
   data comes from each scene's pixels.js, loaded with a <script> element (which works from
   file://, where reading a PNG back through a canvas does not), as zlib data inflated by the
   browser's DecompressionStream. */
(function () {
  'use strict';
  var body = document.body;
  var forEach = function (list, f) { Array.prototype.forEach.call(list, f); };

  // ---- the summary table: click a header to sort, worst first; click again to reverse ----
  var table = document.getElementById('summary');
  function defaultRank(row) { return parseFloat(row.getAttribute('data-rank')); }
  function sortTable(th, column, direction) {
    var numeric = th.getAttribute('data-type') === 'number';
    var tbody = table.tBodies[0];
    var rows = Array.prototype.slice.call(tbody.rows);
    rows.sort(function (a, b) {
      var x = a.cells[column].getAttribute('data-v'), y = b.cells[column].getAttribute('data-v');
      var emptyX = x === null || x === '', emptyY = y === null || y === '';
      if (emptyX || emptyY) return emptyX === emptyY ? defaultRank(a) - defaultRank(b) : (emptyX ? 1 : -1);
      var order = numeric ? parseFloat(x) - parseFloat(y) : x.localeCompare(y);
      if (order === 0 || isNaN(order)) return defaultRank(a) - defaultRank(b);
      return direction === 'ascending' ? order : -order;
    });
    rows.forEach(function (row) { tbody.appendChild(row); });
    forEach(table.tHead.rows[0].cells, function (h) { h.removeAttribute('aria-sort'); });
    th.setAttribute('aria-sort', direction);
  }
  if (table) {
    forEach(table.tHead.rows[0].cells, function (th, column) {
      if (th.getAttribute('data-type') === 'none') return;  // the thumbnails
      th.tabIndex = 0;
      var sort = function () {
        var first = th.getAttribute('data-first') || 'descending';
        var other = first === 'ascending' ? 'descending' : 'ascending';
        sortTable(th, column, th.getAttribute('aria-sort') === first ? other : first);
      };
      th.addEventListener('click', sort);
      th.addEventListener('keydown', function (e) {
        if (e.key === 'Enter' || e.key === ' ') { e.preventDefault(); sort(); }
      });
    });
  }

  // ---- filters: status checkboxes, a name search and "only unexpected", over the table rows,
  //      the list of unexpected results and the scene sections alike ----
  var nameFilter = document.getElementById('filter-name');
  var unexpectedFilter = document.getElementById('filter-unexpected');
  var baselineFilter = document.getElementById('filter-baseline');  // only with a baseline
  function applyFilters() {
    var statuses = {};
    forEach(document.querySelectorAll('input.filter-status'), function (box) { statuses[box.value] = box.checked; });
    var needle = nameFilter ? nameFilter.value.trim().toLowerCase() : '';
    var onlyUnexpected = unexpectedFilter && unexpectedFilter.checked;
    var onlyChanged = baselineFilter && baselineFilter.checked;
    var shown = 0, total = 0;
    forEach(document.querySelectorAll('[data-status][data-name]'), function (el) {
      var visible = statuses[el.getAttribute('data-status')] !== false &&
                    (!onlyUnexpected || el.getAttribute('data-unexpected') === '1') &&
                    (!onlyChanged || !!el.getAttribute('data-baseline')) &&
                    el.getAttribute('data-name').toLowerCase().indexOf(needle) !== -1;
      el.hidden = !visible;
      if (el.tagName === 'TR') { ++total; if (visible) ++shown; }
    });
    var count = document.getElementById('filter-count');
    if (count) count.textContent = shown === total ? '' : shown + ' of ' + total + ' scenes shown';
  }
  forEach(document.querySelectorAll('#filters input'), function (input) {
    input.addEventListener('input', applyFilters);
    input.addEventListener('change', applyFilters);
  });

  // ---- copying the expectations lines (the textarea stays selectable where the clipboard is refused) ----
  var copyButton = document.getElementById('copy-expectations');
  if (copyButton) {
    copyButton.addEventListener('click', function () {
      var text = document.getElementById('expectations-lines');
      var status = document.getElementById('copy-status');
      var done = function () { status.textContent = 'copied'; };
      var fallback = function () {
        text.focus();
        text.select();
        try { status.textContent = document.execCommand('copy') ? 'copied' : 'selected: press Ctrl+C'; }
        catch (err) { status.textContent = 'selected: press Ctrl+C'; }
      };
      if (navigator.clipboard && window.isSecureContext) navigator.clipboard.writeText(text.value).then(done, fallback);
      else fallback();
    });
  }

  // ---- pixel data for the readout, one pixels.js per scene, loaded on demand ----
  var pixelPromises = {};
  var pending = {};
  function bytesOf(base64) {
    var binary = atob(base64);
    var bytes = new Uint8Array(binary.length);
    for (var i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
    return bytes;
  }
  function inflate(base64) {
    if (typeof DecompressionStream === 'undefined') {
      return Promise.reject(new Error('this browser has no DecompressionStream, so no pixel values'));
    }
    var stream = new Blob([bytesOf(base64)]).stream().pipeThrough(new DecompressionStream('deflate'));
    return new Response(stream).arrayBuffer().then(function (buffer) { return new Uint8Array(buffer); });
  }
  window.crosscheckPixels = function (name, d) {
    var waiting = pending[name];
    if (!waiting) return;
    delete pending[name];
    Promise.all([inflate(d.soft), inflate(d.vulkan), inflate(d.softDepth), inflate(d.vulkanDepth)]).then(function (p) {
      var n = d.w * d.h;
      if (p[0].length !== 4 * n || p[1].length !== 4 * n || p[2].length !== 4 * n || p[3].length !== 4 * n) {
        throw new Error('pixel data of ' + name + ' does not match its ' + d.w + 'x' + d.h + ' size');
      }
      waiting.resolve({ w: d.w, h: d.h, soft: p[0], vulkan: p[1],
                        softDepth: new Float32Array(p[2].buffer), vulkanDepth: new Float32Array(p[3].buffer) });
    }).catch(waiting.reject);
  };
  function loadPixels(section) {
    var name = section.getAttribute('data-name');
    if (!section.hasAttribute('data-pixels')) {
      return Promise.reject(new Error('no pixel values kept for ' + name + ' (they are written for scenes outside the tolerance)'));
    }
    if (!pixelPromises[name]) {
      pixelPromises[name] = new Promise(function (resolve, reject) {
        pending[name] = { resolve: resolve, reject: reject };
        var script = document.createElement('script');
        script.src = section.getAttribute('data-pixels');
        script.onerror = function () { reject(new Error('cannot load ' + script.src)); };
        document.head.appendChild(script);
      }).then(function (data) { section.pixelData = data; return data; });
    }
    return pixelPromises[name];
  }

  // ---- the value readout and the marker on the pixel under the pointer ----
  function fmtDepth(z) { return isFinite(z) ? z.toPrecision(9) : String(z); }
  function fmtDelta(d) { return d === 0 ? '0' : (isFinite(d) ? d.toExponential(2) : String(d)); }
  function rgba(a, k) { return a[k] + ' ' + a[k + 1] + ' ' + a[k + 2] + ' ' + a[k + 3]; }
  function describe(d, x, y) {
    var i = y * d.w + x, k = 4 * i, delta = [];
    for (var c = 0; c < 4; ++c) delta.push(Math.abs(d.soft[k + c] - d.vulkan[k + c]));
    var zs = d.softDepth[i], zv = d.vulkanDepth[i];
    return 'x ' + x + ', y ' + y + '  |  softraster RGBA ' + rgba(d.soft, k) + '  |  Vulkan RGBA ' + rgba(d.vulkan, k) +
           '  |  |\u0394| ' + delta.join(' ') + '  |  depth softraster ' + fmtDepth(zs) + ', Vulkan ' + fmtDepth(zv) +
           ', |\u0394| ' + fmtDelta(Math.abs(zs - zv));
  }
  function placeMarkers(section, x, y, scale) {
    forEach(section.querySelectorAll('.view .marker'), function (m) {
      if (x < 0 || scale < 3) { m.style.display = 'none'; return; }
      m.style.display = 'block';
      m.style.left = (x * scale) + 'px';
      m.style.top = (y * scale) + 'px';
      m.style.width = m.style.height = scale + 'px';
    });
  }
  document.addEventListener('mousemove', function (e) {
    var img = e.target;
    if (!(img instanceof HTMLImageElement) || !img.closest('.view')) return;
    var section = img.closest('details.scene');
    if (!section) return;
    var w = +section.getAttribute('data-w'), h = +section.getAttribute('data-h');
    var rect = img.getBoundingClientRect();
    if (!rect.width || !rect.height) return;
    var x = Math.floor((e.clientX - rect.left) / rect.width * w), y = Math.floor((e.clientY - rect.top) / rect.height * h);
    if (x < 0 || y < 0 || x >= w || y >= h) return;
    placeMarkers(section, x, y, rect.width / w);
    var out = section.querySelector('.readout');
    if (section.pixelData) { out.textContent = describe(section.pixelData, x, y); return; }
    out.textContent = 'x ' + x + ', y ' + y + '  |  loading pixel values\u2026';
    loadPixels(section).then(function (d) { out.textContent = describe(d, x, y); },
                             function (err) { out.textContent = 'x ' + x + ', y ' + y + '  |  ' + err.message; });
  });

  // ---- per-scene tools: zoom (nearest-neighbour), synchronised scrolling, flicker ----
  function applyZoom(section, value) {
    var w = +section.getAttribute('data-w');
    forEach(section.querySelectorAll('.view'), function (view) {
      if (value === 'fit') view.classList.remove('zoomed');
      else view.classList.add('zoomed');
      forEach(view.querySelectorAll('img'), function (img) { img.style.width = value === 'fit' ? '' : (w * +value) + 'px'; });
    });
    placeMarkers(section, -1, -1, 0);
  }
  function setUpSection(section) {
    if (section.hasAttribute('data-set-up')) return;
    section.setAttribute('data-set-up', '1');
    // The images come into the page only now (see report.hpp).
    var template = section.querySelector('template.scene-views');
    if (template) template.parentNode.replaceChild(template.content.cloneNode(true), template);
    var zoom = section.querySelector('select.zoom');
    if (zoom) {
      zoom.addEventListener('change', function () { applyZoom(section, zoom.value); });
      if (zoom.value !== 'fit') applyZoom(section, zoom.value);
    }
    var blendMode = section.querySelector('select.blend-mode'), blendAmount = section.querySelector('input.blend-amount');
    if (blendMode && blendAmount) {
      var top = section.querySelector('img.stack-top');
      var blend = function () {
        var amount = +blendAmount.value;
        if (blendMode.value === 'onion') { top.style.opacity = amount / 100; top.style.clipPath = ''; }
        else { top.style.opacity = 1; top.style.clipPath = 'inset(0 0 0 ' + (100 - amount) + '%)'; }
      };
      blendAmount.addEventListener('input', blend);
      blendMode.addEventListener('change', blend);
    }
    var views = section.querySelectorAll('.view');
    forEach(views, function (view) {
      view.addEventListener('scroll', function () {
        forEach(views, function (other) {
          if (other !== view && (other.scrollLeft !== view.scrollLeft || other.scrollTop !== view.scrollTop)) {
            other.scrollLeft = view.scrollLeft;
            other.scrollTop = view.scrollTop;
          }
        });
      });
    });
    // An MSAA scene's sample menu: the images with a data-samples list show the picked sample.
    var samplePick = section.querySelector('select.sample-pick');
    if (samplePick) {
      samplePick.addEventListener('change', function () {
        var n = +samplePick.value;
        forEach(section.querySelectorAll('img[data-samples]'), function (img) {
          img.src = img.getAttribute('data-samples').split(' ')[n];
        });
        forEach(section.querySelectorAll('.sample-label'), function (label) { label.textContent = String(n); });
      });
    }
    var flickerImg = section.querySelector('img.flicker');
    if (flickerImg) {
      var label = section.querySelector('.flicker-label');
      var flickButton = section.querySelector('button.flick');
      var timer = null;
      var show = function (which) {
        flickerImg.setAttribute('data-showing', which);
        flickerImg.src = flickerImg.getAttribute(which === 'a' ? 'data-a' : 'data-b');
        label.textContent = which === 'a' ? 'softraster' : 'Vulkan';
      };
      var swap = function () { show(flickerImg.getAttribute('data-showing') === 'a' ? 'b' : 'a'); };
      section.querySelector('button.swap').addEventListener('click', swap);
      flickButton.addEventListener('click', function () {
        if (timer) { clearInterval(timer); timer = null; flickButton.textContent = 'flicker'; return; }
        timer = setInterval(swap, 500);
        flickButton.textContent = 'stop flicker';
      });
      section.addEventListener('toggle', function () {
        if (!section.open && timer) { clearInterval(timer); timer = null; flickButton.textContent = 'flicker'; }
      });
    }
  }
  document.addEventListener('toggle', function (e) {
    var section = e.target;
    if (section.matches && section.matches('details.scene') && section.open) {
      setUpSection(section);
      if (section.hasAttribute('data-pixels')) loadPixels(section).catch(function () {});
    }
  }, true);
  forEach(document.querySelectorAll('details.scene[open]'), setUpSection);

  // ---- #s-3 or #scene=NAME opens that scene ----
  function openFromHash() {
    var hash;
    try { hash = decodeURIComponent(location.hash.slice(1)); } catch (err) { return; }
    var section = null;
    if (hash.indexOf('scene=') === 0) {
      var name = hash.slice(6);
      forEach(document.querySelectorAll('details.scene'), function (d) {
        if (!section && d.getAttribute('data-name') === name) section = d;
      });
    } else if (hash) {
      var el = document.getElementById(hash);
      if (el && el.matches('details.scene')) section = el;
    }
    if (section) { section.open = true; setUpSection(section); section.scrollIntoView(); }
  }
  window.addEventListener('hashchange', openFromHash);
  openFromHash();

  // ---- self-check: index.html?check opens every scene, loads every image eagerly and every
  //      pixels.js, and records the outcome on <body> for a headless browser's DOM dump ----
  function settle(img) {
    return new Promise(function (resolve) {
      var done = function () { resolve(img.complete && img.naturalWidth > 0); };
      if (img.complete) { done(); return; }
      img.addEventListener('load', done, { once: true });
      img.addEventListener('error', done, { once: true });
    });
  }
  // Moves the pointer over the middle of the first scene's first image and returns the readout.
  function readoutProbe() {
    var img = document.querySelector('details.scene[data-pixels] .view img');
    if (!img) return Promise.resolve('no scene with pixel data');
    var section = img.closest('details.scene');
    return loadPixels(section).then(function () {
      var rect = img.getBoundingClientRect();
      img.dispatchEvent(new MouseEvent('mousemove', { bubbles: true, clientX: rect.left + rect.width / 2,
                                                      clientY: rect.top + rect.height / 2 }));
      return section.querySelector('.readout').textContent;
    });
  }
  // Sorts the table by scene name, Z to A (two header clicks), returns the names in order and
  // restores the default order; and swaps the first flicker view, returning the image it shows.
  function sortProbe() {
    if (!table) return '';
    var headers = table.tHead.rows[0].cells, scene = 0;
    forEach(headers, function (th, column) { if (th.textContent === 'scene') scene = column; });
    headers[scene].click();
    headers[scene].click();
    var names = Array.prototype.map.call(table.tBodies[0].rows, function (row) { return row.cells[scene].getAttribute('data-v'); });
    headers[0].click();
    if (headers[0].getAttribute('aria-sort') !== 'ascending') headers[0].click();
    return names.join(',');
  }
  function flickerProbe() {
    var img = document.querySelector('img.flicker');
    if (!img) return '';
    img.closest('details.scene').querySelector('button.swap').click();
    var shown = img.getAttribute('src');
    img.closest('details.scene').querySelector('button.swap').click();
    return shown;
  }
  // Picks sample 3 in the first MSAA scene's sample menu and returns the three images it shows
  // then and the label, then picks sample 0 again.
  function sampleProbe() {
    var pick = document.querySelector('select.sample-pick');
    if (!pick) return '';
    var section = pick.closest('details.scene');
    var choose = function (n) { pick.value = String(n); pick.dispatchEvent(new Event('change')); };
    choose(3);
    var shown = Array.prototype.map.call(section.querySelectorAll('img[data-samples]'), function (img) { return img.getAttribute('src'); });
    shown.push(section.querySelector('.sample-label').textContent);
    choose(0);
    return shown.join(' ');
  }
  // Filters: "only unexpected", then the name "depth", then back; returns the visible row counts.
  function filterProbe() {
    if (!table || !unexpectedFilter || !nameFilter) return '';
    var visible = function () {
      return Array.prototype.filter.call(table.tBodies[0].rows, function (row) { return !row.hidden; }).length;
    };
    var counts = [visible()];
    unexpectedFilter.checked = true; applyFilters(); counts.push(visible());
    unexpectedFilter.checked = false; nameFilter.value = 'depth'; applyFilters(); counts.push(visible());
    nameFilter.value = ''; applyFilters();
    return counts.join(',');
  }
  // The marks against the baseline in the table's default order ("name:mark mark,..."), the summary
  // line, and how many rows "only changed against the baseline" leaves.
  function baselineProbe() {
    if (!table) return;
    var marks = [];
    forEach(table.tBodies[0].rows, function (row) {
      var shown = Array.prototype.map.call(row.querySelectorAll('.mark'), function (m) { return m.textContent; });
      if (shown.length) marks.push(row.getAttribute('data-name') + ':' + shown.join('+'));
    });
    body.setAttribute('data-baseline-marks', marks.join(','));
    var summary = document.getElementById('baseline-summary');
    body.setAttribute('data-baseline-summary', summary ? summary.textContent : '');
    body.setAttribute('data-baseline-changed-cells', String(table.querySelectorAll('td.changed').length));
    if (baselineFilter) {
      baselineFilter.checked = true; applyFilters();
      body.setAttribute('data-baseline-filter', String(Array.prototype.filter.call(table.tBodies[0].rows,
                                                                                 function (row) { return !row.hidden; }).length));
      baselineFilter.checked = false; applyFilters();
    }
  }
  function selfCheck() {
    body.setAttribute('data-check', 'running');
    forEach(document.querySelectorAll('details.scene'), function (d) { d.open = true; setUpSection(d); });
    var images = Array.prototype.slice.call(document.images);
    images.forEach(function (img) { img.loading = 'eager'; });
    var sections = Array.prototype.slice.call(document.querySelectorAll('details.scene[data-pixels]'));
    var pixelErrors = [];
    Promise.all([
      Promise.all(images.map(settle)),
      Promise.all(sections.map(function (s) {
        return loadPixels(s).then(function (d) { describe(d, 0, 0); return true; },
                                  function (err) { pixelErrors.push(err.message); return false; });
      }))
    ]).then(function (r) {
      var loaded = r[0].filter(Boolean).length, pixels = r[1].filter(Boolean).length;
      var failed = images.filter(function (img, i) { return !r[0][i]; }).map(function (img) { return img.getAttribute('src'); });
      body.setAttribute('data-images-loaded', loaded + '/' + images.length);
      body.setAttribute('data-images-failed', String(images.length - loaded));
      if (failed.length) body.setAttribute('data-images-failed-list', failed.join(' '));
      body.setAttribute('data-pixels-loaded', pixels + '/' + sections.length);
      if (pixelErrors.length) body.setAttribute('data-pixels-errors', pixelErrors.join(' | '));
      body.setAttribute('data-summary-rows', table ? String(table.tBodies[0].rows.length) : '0');
      body.setAttribute('data-sort-probe', sortProbe());
      body.setAttribute('data-flicker-probe', flickerProbe());
      body.setAttribute('data-sample-probe', sampleProbe());
      body.setAttribute('data-filter-probe', filterProbe());
      baselineProbe();
      var lines = document.getElementById('expectations-lines');
      body.setAttribute('data-expectations-lines', lines ? lines.value.replace(/\n/g, ' | ') : '');
      body.setAttribute('data-thumbnails', String(document.querySelectorAll('img.thumb').length));
      // The chart: inline SVG panels (as SVG elements, so the browser parsed them as SVG), their
      // markers, the markers' tooltips, the Pareto fronts and the stability table's rows.
      var panels = document.querySelectorAll('svg.chart-panel');
      var markers = document.querySelectorAll('svg.chart-panel g.marker');
      var titled = Array.prototype.filter.call(markers, function (m) {
        var t = m.querySelector('title');
        return t && t.textContent.length > 0;
      });
      body.setAttribute('data-chart-panels', String(panels.length));
      body.setAttribute('data-chart-svg', String(Array.prototype.every.call(panels, function (p) {
        return p instanceof SVGSVGElement;
      })));
      body.setAttribute('data-chart-markers', String(markers.length));
      body.setAttribute('data-chart-tooltips', String(titled.length));
      body.setAttribute('data-chart-pareto', String(document.querySelectorAll('svg.chart-panel polyline.pareto').length));
      var stability = document.getElementById('stability-table');
      body.setAttribute('data-stability-rows', stability ? String(stability.tBodies[0].rows.length) : '0');
      return readoutProbe();
    }).then(function (readout) {
      body.setAttribute('data-readout', readout);
      body.setAttribute('data-check', 'done');
    }, function (err) {
      body.setAttribute('data-check', 'error: ' + err.message);
    });
  }
  if (/(^\?|&)check(=|&|$)/.test(location.search) || location.hash === '#check') selfCheck();
  body.setAttribute('data-ready', '1');
  body.setAttribute('data-ready-ms', String(Math.round(performance.now())));  // for measuring the page
})();
