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
  // the shadow ray's test (black: a shadow), its blocker and where it meets it
  b_s: '#000000', c_s: '#000000', delta_s: '#000000', s_1: '#000000', s_2: '#000000', s: '#000000',
  NK: '#000000', s_own: '#000000', blocker: '#000000',
};

export function quantityColour(key) {
  return colours[key] || '#555555';
}
