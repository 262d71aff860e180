import type { Catalogue } from './en.ts';

/**
 * The Japanese catalogue, in the paper's own terms (薄膜干渉, 膜厚, 屈折率, 入射角, 反射率, 偏光,
 * 光源, 等色関数, 色空間). Typed by the English one's keys, so a missing or extra key is a type error.
 */
export const JA: Catalogue = {
  'common.thinFilmInterference': '薄膜干渉',
  'common.thickness': '膜厚 d (nm)',
  'common.angle': '入射角 θi (°)',
  'common.wavelength': '波長 λ (nm)',
  'common.nOutside': '外側の媒質の屈折率 n_a',
  'common.nFilm': '薄膜の屈折率 n_b',
  'common.nInside': '内側の媒質の屈折率 n_c',
  'common.reflectance': '反射率 R',
  'common.polarization': '偏光',
  'common.polarization.unpolarized': '非偏光：R = (R_s + R_p)/2',
  'common.polarization.paper': '論文の方式：振幅反射率と振幅透過率を平均（式 (4), (8)）',
  'common.polarization.s': 's 偏光',
  'common.polarization.p': 'p 偏光',
  'common.illuminant': '光源',
  'common.colorMatchingFunctions': '等色関数',
  'common.colorSpace': '色空間',
  'common.unit.nm': 'nm',
  'common.unit.degrees': '°',
  'diagram.label': '薄膜干渉の図',
  'diagram.controls': '設定',
  'diagram.figureTitle': '薄膜干渉の原理：反射光',
  'diagram.figureDescription':
    '上に媒質 a（n_a = {na}）、中に薄膜 b（膜厚 {thickness} nm、n_b = {nb}）、下に媒質 c（n_c = {nc}）。' +
    '入射光は入射角 θi = {angle}° で薄膜に入り、屈折角 θri = {refracted} で屈折する。' +
    '反射光 E0 から E{last} までの {count} 本を、振幅 |E_n| に比例した太さで描いている：{amplitudes}。',
  'diagram.mediumA': '媒質 a：n_a = {n}',
  'diagram.mediumB': '媒質 b（薄膜、d = {thickness} nm）：n_b = {n}',
  'diagram.mediumC': '媒質 c：n_c = {n}',
  'diagram.drawnAngle': '反射光が重ならないよう、角度は {angle}° で描いている',
  'diagram.incident': '入射光',
  'diagram.evanescent': '複素数（薄膜内はエバネッセント波）',
  'diagram.backTotalReflection': '裏面で全反射',
  'diagram.opticalPath': 'Δ = 2 n_b d cos θri = {delta} nm（式 (12)）',
  'diagram.opticalPathEvanescent': 'Δ = 2 n_b d cos θri = {delta} nm（虚数）',
  'diagram.beamsCaption': '反射光の電場（入射光の電場に対する比）',
  'diagram.beam': '反射光',
  'diagram.amplitude': '振幅',
  'diagram.magnitude': '|E_n|（{channel}）',
  'diagram.tail': '残りの項',
  'diagram.total': 'E：総和（式 (13)）',
  'diagram.phasorTitle': 'フェーザ図：{channel}',
  'diagram.phasorDescription': '複素平面上で E0, E1, … を順につなぐと E = {total} に収束し、|E|² = R = {reflectance} となる。',
  'diagram.spectrumTitle': '反射率 R(λ)：380〜830 nm',
  'diagram.spectrumDescription':
    '可視域の反射率の曲線。波長 λ = {wavelength} nm に印があり、そこでの R = {reflectance}。' +
    '薄膜の色は、この曲線に光源のスペクトルを掛け、等色関数で重み付けして色空間で表したものである。',
  'diagram.flipTop': '上面での位相反転なし',
  'diagram.flipTopHint':
    'E0 の r_ab の符号だけを反転する。屈折率の大きい媒質で反射した光は符号が反転する。それがなければ、ごく薄い膜はほぼ (2 r_ab)² を反射し、黒ではなく明るく見えるはずである。',
  'diagram.flipTopNote': '仮想：上面での位相反転なし',
  'diagram.summary': '反射率 R = {reflectance}（波長 λ = {wavelength} nm、{polarization}）。',
  'diagram.summaryBeams': '反射光を {count} 本描いた。残りの項の和は入射光の振幅の {bound} 以下である。',
  'diagram.summaryTail': '反射光を {count} 本描いた。残りの項（入射光の振幅の {bound} 以下）は式 (13) の閉じた形で加えている。',
  'diagram.summaryDiverges':
    '反射光を {count} 本描いた。ここでは級数が収束しない（|r_ba r_bc e^{iφ}| = 1）ので、E は式 (13) の閉じた形による。',
  'diagram.summaryNoEntry': '光は薄膜に入らない（すれすれの入射）：反射光は E0 だけである。',
  'diagram.error.number': '{attribute}={value} は使えない：{min} から {max}{unit} までの数値を指定すること。',
  'diagram.error.choice': '{attribute}={value} は使えない：{choices} のいずれかを指定すること。',
  'diagram.error.filmIndex':
    '{attribute}={value} は使えない：{min} から {max} までの数値、{materials}、またはその範囲に収まる {cauchy} を指定すること。',
  'diagram.error.for': '{attribute}={value}：その id の {tag} がこのページにない。',
};
