const canvas = document.querySelector<HTMLCanvasElement>('#bubble');
if (!canvas) throw new Error('index.html must hold <canvas id="bubble">');
const gl = canvas.getContext('webgl2');
document.body.dataset.webgl2 = gl ? 'yes' : 'no';
