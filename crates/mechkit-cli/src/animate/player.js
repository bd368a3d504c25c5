// mechkit's animation player: draws the frames of the data in #mechkit-data on the canvas
// #scene as `mechkit animate --format gif` draws them (the layout is computed by mechkit and
// comes with the data), plays them at the animation's frame rate, looping, with a play/pause
// button (#play), a slider over the frames (#slider) and the time (#time).
//
// For tests: window.mechkitPlayer = {frame(), frames, playing(), play(), pause(), seek(i)}.
(function () {
  'use strict';

  // pixel coordinates are kept within this distance of the picture (as mechkit does)
  var FAR = 1e6;

  var data = JSON.parse(document.getElementById('mechkit-data').textContent);
  var layout = data.layout;
  var map = layout.map;
  var canvas = document.getElementById('scene');
  var button = document.getElementById('play');
  var slider = document.getElementById('slider');
  var timeLabel = document.getElementById('time');
  var context = canvas.getContext('2d');
  var width = layout.size[0];
  var height = layout.size[1];
  var ratio = window.devicePixelRatio || 1;
  var count = data.frames.length;

  // a sharp picture on screens with several device pixels to a CSS pixel
  canvas.width = Math.round(width * ratio);
  canvas.height = Math.round(height * ratio);
  canvas.style.width = width + 'px';
  slider.max = String(Math.max(count - 1, 0));

  function limit(v, lo, hi) {
    return Math.max(lo, Math.min(hi, v));
  }

  // the pixel of the world point (x, y): y up in the world, down on the canvas
  function px(x, y) {
    return [
      limit(map.left + (x - map.x_min) * map.scale, -FAR, FAR),
      limit(map.bottom - (y - map.y_min) * map.scale, -FAR, FAR)
    ];
  }

  function stroke(colour, lineWidth) {
    if (lineWidth > 0) {
      context.strokeStyle = colour;
      context.lineWidth = lineWidth;
      context.lineJoin = 'round';
      context.lineCap = 'round';
      context.stroke();
    }
  }

  // shape: [style, kind, numbers...]; kind 0 circle, 1 dot, 2 polygon, 3 polyline
  function drawShape(shape) {
    var style = data.styles[shape[0]];
    var kind = shape[1];
    var i, p;
    context.beginPath();
    if (kind === 0 || kind === 1) {
      p = px(shape[2], shape[3]);
      var r = kind === 0 ? shape[4] * map.scale : shape[4];
      context.arc(p[0], p[1], Math.min(r, FAR), 0, 2 * Math.PI);
    } else {
      for (i = 2; i + 1 < shape.length; i += 2) {
        p = px(shape[i], shape[i + 1]);
        if (i === 2) {
          context.moveTo(p[0], p[1]);
        } else {
          context.lineTo(p[0], p[1]);
        }
      }
      if (kind === 2) {
        context.closePath();
      }
    }
    if (style[0] !== null) {
      context.fillStyle = style[0];
      context.fill();
    }
    if (style[1] !== null) {
      stroke(style[1], style[2]);
    }
  }

  // trail: [colour, [x0, y0, x1, y1, ...]], drawn to point `last`, broken at nulls
  function drawTrail(trail, last) {
    var points = trail[1];
    var end = Math.min(last + 1, points.length / 2);
    var run = 0;
    context.beginPath();
    for (var i = 0; i < end; i++) {
      var x = points[2 * i];
      var y = points[2 * i + 1];
      if (x === null || y === null) {
        run = 0;
        continue;
      }
      var p = px(x, y);
      if (run === 0) {
        context.moveTo(p[0], p[1]);
      } else {
        context.lineTo(p[0], p[1]);
      }
      run++;
    }
    context.globalAlpha = layout.trail_opacity;
    stroke(trail[0], layout.trail_width);
    context.globalAlpha = 1;
  }

  function drawText(text, content) {
    var s = content === undefined ? text.content : content;
    if (!s) {
      return;
    }
    context.font = text.size + 'px "DejaVu Sans", sans-serif';
    context.fillStyle = text.colour;
    context.textAlign = text.align;
    context.textBaseline = 'alphabetic';
    context.fillText(s, text.x, text.y);
  }

  function line(points, colour, lineWidth) {
    context.beginPath();
    context.moveTo(points[0], points[1]);
    for (var i = 2; i + 1 < points.length; i += 2) {
      context.lineTo(points[i], points[i + 1]);
    }
    context.strokeStyle = colour;
    context.lineWidth = lineWidth;
    context.lineJoin = 'miter';
    context.lineCap = 'butt';
    context.stroke();
  }

  function timeStamp(t) {
    return t === null ? 't = ? s' : 't = ' + t.toFixed(3) + ' s';
  }

  function drawScene(index) {
    var scene = layout.scene;
    context.save();
    context.beginPath();
    context.rect(scene.x0, scene.y0, scene.x1 - scene.x0, scene.y1 - scene.y0);
    context.clip();
    data.background.forEach(drawShape);
    if (index >= 0) {
      data.trails.forEach(function (trail) {
        drawTrail(trail, index);
      });
      data.frames[index][1].forEach(drawShape);
    }
    context.restore();
  }

  function drawEnergy(panel, values) {
    var y = function (v) {
      v = limit(v, panel.lo, panel.hi);
      return panel.bottom - (v - panel.lo) / (panel.hi - panel.lo) * (panel.bottom - panel.top);
    };
    var zero = y(0);
    line([panel.separator, 0, panel.separator, height], layout.track, 1);
    drawText(panel.heading);
    panel.bars.forEach(function (bar, i) {
      context.fillStyle = layout.track;
      context.fillRect(bar.x0, panel.top, bar.x1 - bar.x0, panel.bottom - panel.top);
      var v = values[i];
      if (typeof v === 'number') {
        var top = y(v);
        context.fillStyle = bar.colour;
        context.fillRect(bar.x0, Math.min(top, zero), bar.x1 - bar.x0, Math.abs(top - zero));
      }
      drawText(bar.label);
    });
    line([panel.axis, panel.top, panel.axis, panel.bottom], layout.axis, 1);
    line([panel.axis, zero, panel.right, zero], layout.axis, 1);
    panel.ticks.forEach(function (tick) {
      drawText(tick);
    });
  }

  // frame `index` (-1: no frame, the background alone), as mechkit's SVG draws it
  function draw(index) {
    var frame = index >= 0 ? data.frames[index] : null;
    context.setTransform(ratio, 0, 0, ratio, 0, 0);
    context.fillStyle = '#ffffff';
    context.fillRect(0, 0, width, height);
    drawScene(index);
    if (frame) {
      drawText(layout.time, timeStamp(frame[0]));
    }
    drawText(layout.title);
    var bar = layout.scale_bar;
    if (bar) {
      var top = bar.y - bar.tick;
      line([bar.x0, top, bar.x0, bar.y, bar.x1, bar.y, bar.x1, top], bar.colour, bar.width);
      drawText(bar.label);
    }
    if (layout.panel) {
      drawEnergy(layout.panel, frame ? frame[2] : []);
    }
  }

  var current = 0;
  var playing = false;
  var started = 0;
  var startFrame = 0;
  var request = 0;

  function show(index) {
    current = index;
    slider.value = String(index);
    timeLabel.textContent = count > 0 ? timeStamp(data.frames[index][0]) : '';
    draw(count > 0 ? index : -1);
  }

  function tick(now) {
    if (!playing) {
      return;
    }
    // a frame's timestamp may precede the play() or seek() that asked for it
    var elapsed = Math.max(0, now - started);
    var index = (startFrame + Math.floor(elapsed * data.fps / 1000)) % count;
    if (index !== current) {
      show(index);
    }
    request = window.requestAnimationFrame(tick);
  }

  function play() {
    if (playing || count === 0) {
      return;
    }
    playing = true;
    started = window.performance.now();
    startFrame = current;
    button.textContent = 'Pause';
    button.setAttribute('aria-label', 'Pause');
    request = window.requestAnimationFrame(tick);
  }

  function pause() {
    playing = false;
    window.cancelAnimationFrame(request);
    button.textContent = 'Play';
    button.setAttribute('aria-label', 'Play');
  }

  function seek(index) {
    if (count === 0) {
      return;
    }
    show(limit(Math.round(Number(index)) || 0, 0, count - 1));
    started = window.performance.now();
    startFrame = current;
  }

  button.addEventListener('click', function () {
    if (playing) {
      pause();
    } else {
      play();
    }
  });
  slider.addEventListener('input', function () {
    pause();
    seek(slider.value);
  });

  window.mechkitPlayer = {
    frame: function () {
      return current;
    },
    frames: count,
    playing: function () {
      return playing;
    },
    play: play,
    pause: pause,
    seek: seek
  };

  show(0);
  if (count === 0) {
    pause();
    button.disabled = true;
    slider.disabled = true;
  } else {
    play();
  }
})();
