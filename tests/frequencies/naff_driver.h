/* arnoldweb tests: the frequency analysis of one trajectory's signal, as a
 * kernel would run it (lib/device/aw_naff.h): `terms` times the coarse FFT
 * peak, the refinement, and the subtraction of the term found. Portable like
 * the device core: the host tests include it (double and float) and the
 * OpenCL test compiles it, and the two must give the same bits.
 *
 * Layout, coalesced over a chunk of `count` trajectories: sample k of
 * trajectory j at re[k count + j], im[k count + j]; the FFT work buffer
 * likewise (2^log2m rows); results at out[(j terms + t) 5 + 0..4]: frequency
 * (cycles per sample), amplitude (re, im), passes, ok. */
#ifndef NAFF_DRIVER_H
#define NAFF_DRIVER_H

AW_FN void naff_test_analyse(AW_GLOBAL real* re, AW_GLOBAL real* im, AW_GLOBAL real* wre, AW_GLOBAL real* wim,
                             AW_GLOBAL real* out, int j, int count, int n, int p, int terms, int log2m) {
  const aw_u64 stride = (aw_u64)count;
  for (int t = 0; t < terms; ++t) {
    const real coarse = aw_naff_fft_peak(re + j, im + j, stride, n, p, wre + j, wim + j, stride, log2m);
    aw_naff_result r;
    aw_naff_refine(re + j, im + j, stride, n, p, coarse, &r);
    AW_GLOBAL real* o = out + ((aw_u64)j * (aw_u64)terms + (aw_u64)t) * 5u;
    o[0] = r.freq;
    o[1] = r.amp_re;
    o[2] = r.amp_im;
    o[3] = (real)r.passes;
    o[4] = (real)r.ok;
    aw_naff_subtract(re + j, im + j, stride, n, r.freq, r.amp_re, r.amp_im);
  }
}

#endif /* NAFF_DRIVER_H */
