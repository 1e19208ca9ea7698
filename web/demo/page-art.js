// Draws the demo's two page sides on canvas at run time (no image files to ship): a text page with a
// heading, paragraphs and a drawing on the front, and a figure page on the back.
const WIDTH = 800;
const HEIGHT = 1000;

const WORDS = ('the page lifts from its corner and rolls over a cone whose apex slides along the spine ' +
  'while the cone narrows and the paper follows it bending but never stretching until the leaf ' +
  'settles flat on the other side light falls across the curl and the back of the sheet shows ' +
  'through as the turn completes').split(' ');

function paragraph(g, x, y, width, lines, seed) {
  g.font = '22px "DejaVu Serif", serif';
  g.fillStyle = '#2b2b2b';
  let word = seed;
  for (let line = 0; line < lines; line++) {
    let text = '';
    while (g.measureText(`${text} ${WORDS[word % WORDS.length]}`).width < width) {
      text += (text ? ' ' : '') + WORDS[word % WORDS.length];
      word += 1;
    }
    g.fillText(line === lines - 1 ? text.split(' ').slice(0, 5).join(' ') + '.' : text, x, y + line * 34);
  }
}

function paper(g, tint) {
  g.fillStyle = tint;
  g.fillRect(0, 0, WIDTH, HEIGHT);
  g.strokeStyle = 'rgba(0,0,0,0.08)';
  g.lineWidth = 2;
  g.strokeRect(1, 1, WIDTH - 2, HEIGHT - 2);
}

export function drawFront() {
  const canvas = Object.assign(document.createElement('canvas'), { width: WIDTH, height: HEIGHT });
  const g = canvas.getContext('2d');
  paper(g, '#fbf8f1');
  g.fillStyle = '#7a2e1f';
  g.font = 'bold 54px "DejaVu Serif", serif';
  g.fillText('Chapter One', 70, 130);
  g.fillStyle = '#555';
  g.font = 'italic 26px "DejaVu Serif", serif';
  g.fillText('In which a page learns to curl', 72, 175);
  paragraph(g, 70, 250, 660, 6, 0);
  // A small drawing: the cone the page wraps around.
  g.save();
  g.translate(400, 610);
  g.strokeStyle = '#3b5b8c';
  g.lineWidth = 4;
  g.beginPath();
  g.moveTo(0, 150); g.lineTo(-120, -80); g.moveTo(0, 150); g.lineTo(120, -80);
  g.stroke();
  g.beginPath();
  g.ellipse(0, -80, 120, 26, 0, 0, Math.PI * 2);
  g.stroke();
  g.restore();
  paragraph(g, 70, 820, 660, 2, 3);
  g.fillStyle = '#888';
  g.font = '22px "DejaVu Serif", serif';
  g.textAlign = 'center';
  g.fillText('1', WIDTH / 2, 965);
  return canvas;
}

export function drawBack() {
  const canvas = Object.assign(document.createElement('canvas'), { width: WIDTH, height: HEIGHT });
  const g = canvas.getContext('2d');
  paper(g, '#f6f1e6');
  g.fillStyle = '#1f4e7a';
  g.font = 'bold 44px "DejaVu Serif", serif';
  g.fillText('Figure 1', 70, 120);
  // A landscape: sky, hills, sun. Asymmetric, so a mirrored back would be obvious.
  g.fillStyle = '#cfe3f2';
  g.fillRect(70, 160, 660, 420);
  g.fillStyle = '#f2b632';
  g.beginPath(); g.arc(620, 250, 50, 0, Math.PI * 2); g.fill();
  g.fillStyle = '#6f9d58';
  g.beginPath(); g.moveTo(70, 580); g.quadraticCurveTo(250, 330, 470, 580); g.fill();
  g.fillStyle = '#4f7d3e';
  g.beginPath(); g.moveTo(300, 580); g.quadraticCurveTo(560, 380, 730, 580); g.fill();
  g.fillStyle = '#444';
  g.font = 'italic 24px "DejaVu Serif", serif';
  g.fillText('The back of page 1, read after the turn.', 70, 630);
  paragraph(g, 70, 700, 660, 5, 11);
  g.fillStyle = '#888';
  g.font = '22px "DejaVu Serif", serif';
  g.textAlign = 'center';
  g.fillText('2', WIDTH / 2, 965);
  return canvas;
}
