// Each quantity keeps one colour everywhere: in the derivation, on its 3D
// arrow and label (Okabe-Ito, colour-blind safe).
const colours = {
  E: '#0072B2',
  P: '#D55E00',
  N: '#009E73',
  N_P: '#009E73',
  K: '#E69F00',
  K_P: '#E69F00',
  D: '#E69F00',
  R_hat: '#CC79A7',
  V_hat: '#56B4E9',
};

export function quantityColour(key) {
  return colours[key] || '#555555';
}
