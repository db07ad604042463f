#pragma once
/// @file
/// Units of the whole physics layer (docs/model.md, section 1). Stated here once:
///   lengths      in R, the characteristic punch size;
///   pressures    in E0* = E0 / (1 - nu^2), the instantaneous plane-strain modulus;
///   point loads  in R^2 E0*;
///   time         in T_eps, the creep (retardation) time;
///   creep J(t)   in 1/E0*, relaxation E(t) in E0*.
/// Poisson's ratio never appears: it is folded into E0*. Every double in src/model is in
/// these units; nothing converts.
