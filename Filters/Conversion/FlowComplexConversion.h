// Conversions between VTK data and the core's plain structures (docs/data-contract.md),
// one header per direction; this one gathers them for the filters and the CLI.
#ifndef FlowComplexConversion_h
#define FlowComplexConversion_h

#include "ContractArrays.h"
#include "FlowComplexFromVTK.h"
#include "FlowComplexToVTK.h"
#include "SamplesFromVTK.h"
#include "SimplificationConversion.h"

#endif
