// The blocks Flow Complex Simplification's display shows: the critical points
// and Gabriel edges that survive t_p, beside the complete blocks that keep them all.
#ifndef SurvivingBlocks_h
#define SurvivingBlocks_h

class vtkMultiBlockDataSet;

namespace flowrecon
{

/// Appends to `output` the blocks SurvivingCriticalPoints (the points of
/// CriticalPoints whose `Cancelled` is 0 and their vertex cells) and
/// SurvivingGabrielEdges (the lines of GabrielEdges whose `Cancelled` is 0, over
/// all its points), each with every point and cell array of its source block, in
/// the source's order. A block whose source or `Cancelled` array is missing is
/// left out.
void AddSurvivingBlocks(vtkMultiBlockDataSet* output);

} // namespace flowrecon

#endif
