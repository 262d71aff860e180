// The logarithmic mean L(a, b) = (a − b)/(ln a − ln b) of two non-negative numbers, as
// m·δ/atanh δ (mirrors src/physics/filmDynamics/logarithmicMean.ts; TFC_LOG_MEAN_SERIES_BELOW from there).
#ifndef THIN_FILM_LOGARITHMIC_MEAN
#define THIN_FILM_LOGARITHMIC_MEAN
float tfcLogarithmicMean(float a, float b) {
  float sum = a + b;
  if (sum <= 0.0) return 0.0;
  float delta = (a - b) / sum;
  float mean = 0.5 * sum;
  if (abs(delta) < TFC_LOG_MEAN_SERIES_BELOW) return mean * (1.0 - delta * delta / 3.0);
  if (abs(delta) >= 1.0) return 0.0;
  return mean * delta / atanh(delta);
}
#endif
