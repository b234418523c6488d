#include "ReconstructionReport.h"

#include "FlowReconNames.h"
#include "LocalFlatness.h"
#include "Progress.h" // core: InputError

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <tuple>

namespace flowrecon
{

namespace
{

// The column `name` of `table`, which `what` names in the error.
vtkDataArray* Column(vtkTable* table, const char* name, const char* what)
{
  auto* column = vtkDataArray::SafeDownCast(table->GetColumnByName(name));
  if (!column)
  {
    throw InputError(std::string(what) + " without column " + name);
  }
  return column;
}

} // namespace

std::vector<TopologyStep> TopologyRows(vtkTable* topology)
{
  std::vector<TopologyStep> rows;
  const vtkIdType n = topology ? topology->GetNumberOfRows() : 0;
  if (n == 0)
  {
    return rows;
  }
  vtkDataArray* threshold = Column(topology, names::Threshold, "topology profile");
  vtkDataArray* b[3] = { Column(topology, "b0", "topology profile"),
    Column(topology, "b1", "topology profile"), Column(topology, "b2", "topology profile") };
  for (vtkIdType row = 0; row < n; ++row)
  {
    TopologyStep step;
    step.Threshold = threshold->GetComponent(row, 0);
    for (int k = 0; k < 3; ++k)
    {
      step.Betti[k] = static_cast<Id>(b[k]->GetComponent(row, 0));
    }
    rows.push_back(step);
  }
  return rows;
}

namespace
{
bool BettiNumbersAt(const std::vector<TopologyStep>& rows, double t, std::array<long long, 3>& betti)
{
  if (rows.empty())
  {
    return false;
  }
  std::size_t row = 0;
  while (row + 1 < rows.size() && rows[row + 1].Threshold < t)
  {
    ++row;
  }
  for (int k = 0; k < 3; ++k)
  {
    betti[k] = static_cast<long long>(rows[row].Betti[k]);
  }
  return true;
}
} // namespace

bool BettiNumbersAt(vtkTable* topology, double t, std::array<long long, 3>& betti)
{
  return BettiNumbersAt(TopologyRows(topology), t, betti);
}

namespace
{

std::string Number(double x, int digits)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << x;
  return s.str();
}

std::string Window(const StableWindow& w)
{
  return "(" + Number(w.From, 2) + ", " + Number(w.To, 2) + "]";
}

std::string Betti(const StableWindow& w)
{
  return std::to_string(w.Betti[0]) + " " + std::to_string(w.Betti[1]) + " " +
    std::to_string(w.Betti[2]);
}

std::string Short(double x)
{
  std::ostringstream s;
  s << x;
  return s.str();
}

} // namespace

std::string DescribeChoice(const ThresholdChoice& choice, const std::vector<double>& tps,
  bool trChosen, bool tpChosen)
{
  const double tp = tps.at(choice.Candidate);
  std::string line = "t_r " + Number(choice.ReconstructionThreshold, 3) +
    (trChosen ? " (auto)" : "") + ", t_p " + (std::isnan(tp) ? "of the file" : Short(tp)) +
    (tpChosen ? " (auto)" : "") + ": ";
  if (choice.Window.Length() == 0)
  {
    return line + "no Betti numbers hold over a range of t_r";
  }
  return line + "Betti numbers " + Betti(choice.Window) + ", unchanged for t_r in " +
    Window(choice.Window);
}

std::vector<std::string> ReconstructionChoiceWarnings(const ThresholdChoice& choice)
{
  std::vector<std::string> lines;
  if (choice.Resurfaced)
  {
    // Its own line (below) gives the window taken and the one left.
  }
  else if (choice.Unstable())
  {
    lines.push_back("no stable topology: the Betti numbers hold over no range of t_r of " +
      Number(100 * (choice.Rule.Stable - 1), 0) + " % or more" +
      (choice.Window.Length() > 0 ? " (the longest: " + Window(choice.Window) + ")" : "") +
      "; the sampling may be too sparse or too noisy for this shape");
  }
  else if (choice.Short())
  {
    lines.push_back("the topology holds only for t_r in " + Window(choice.Window) +
      ": an under-sampled region is near (see below)");
  }
  if (choice.ChangesAtStart > 1)
  {
    lines.push_back("at t_r " + Number(choice.Window.From, 2) + ", where these Betti numbers start, " +
      std::to_string(choice.ChangesAtStart) +
      " classes change at once: a cavity may have been filled together with its walls "
      "(a surface sampled with holes)");
  }
  const std::string fewer = "only " + std::to_string(choice.Samples) + " samples, too few to tell whether they "
    "lie on a surface or fill a volume (the flatness test needs " + std::to_string(flowrecon::FlatnessMinimumPoints()) + ")";
  if (choice.Resurfaced && choice.TooFew)
  {
    lines.push_back(fewer + ": the closed surface " + Betti(choice.Window) + ", which holds for t_r in " +
      Window(choice.Window) + ", is taken over the answer without a void (" + Betti(choice.Solid) +
      " above it)");
  }
  else if (choice.TooFew)
  {
    lines.push_back(fewer + ", and no t_r looked at gives a closed surface: the answer, without a void, "
      "is not checked");
  }
  else if (choice.Resurfaced && choice.Solid.Betti[2] == 0)
  {
    lines.push_back("the samples lie on a surface (local flatness " +
      Number(choice.Flatness, 2) + "), yet the most stable topology is a solid without a void: "
      "a closed surface sampled too sparsely or too noisily for its thickness may have been "
      "filled in; the closed surface " + Betti(choice.Window) + ", which holds only for t_r in " +
      Window(choice.Window) + ", is taken instead");
  }
  else if (choice.Resurfaced)
  {
    lines.push_back("the samples lie on a surface (local flatness " +
      Number(choice.Flatness, 2) + "), yet the most stable topology (" + Betti(choice.Solid) +
      ") is solid around its voids: the space between nested closed surfaces, sampled too sparsely "
      "for its width, may have been filled in; the closed surfaces " + Betti(choice.Window) +
      ", which hold only for t_r in " + Window(choice.Window) + ", are taken instead");
  }
  // Solid around voids without a window with more: not said, as a noisy
  // closed surface's answer is that too (a shell a few spacings thick).
  else if (choice.Filled && choice.Window.Betti[2] == 0)
  {
    lines.push_back("the samples lie on a surface (local flatness " +
      Number(choice.Flatness, 2) + "), yet the reconstruction is solid, without a void (" +
      std::to_string(choice.Maxima) + " maxima for " + std::to_string(choice.Samples) +
      " samples): a closed surface sampled too sparsely or too noisily for its thickness "
      "may have been filled in");
  }
  if (choice.Shallow)
  {
    lines.push_back("the reconstruction is solid but shallow: every sample is within " +
      std::to_string(choice.Depth) + " Delaunay edge" + (choice.Depth == 1 ? "" : "s") +
      " of its boundary, so a closed surface with noise of about its sample spacing "
      "may have been filled in (a solid sampled through its volume is deeper)");
  }
  if (choice.Far.Count > 0)
  {
    const bool one = choice.Far.Count == 1;
    lines.push_back(std::to_string(choice.Far.Count) + (one ? " sample lies" : " samples lie") +
      " apart from the rest (the nearest sample over " + Number(choice.Rule.FarFactor, 0) +
      " times the median distance away; " + (one ? "it is" : "the farthest,") + " " +
      Number(choice.Far.Largest, 1) + " times, near " + PlaceText(choice.Far.Farthest, choice.Far.Median) +
      "): outliers, or a region sampled far more sparsely; the reconstruction grows through "
      "them, and can fill a closed surface or join parts");
  }
  if (choice.Apart.Length() > 0)
  {
    // Three digits: the range can be narrow, and it is advice to follow.
    lines.push_back(std::to_string(choice.Apart.Betti[0]) + " closed surfaces were apart for t_r in (" +
      Number(choice.Apart.From, 3) + ", " + Number(choice.Apart.To, 3) + "] (Betti numbers " + Betti(choice.Apart) + ") and are joined in the answer: "
      "a gap between separate surfaces, about as wide as the sample spacing, may have been bridged "
      "(a t_r in that range keeps them apart)");
  }
  if (choice.Rows > 0)
  {
    const std::string within = choice.RowGapOfExtent > 0
      ? "closed curves side by side, none with a void, each within " + Number(choice.RowGapOfExtent, 2) +
        " times its extent of another (the widest gap " + Number(choice.RowGap, 1) +
        " times the median sample spacing, near "
      : "parts side by side, none with a void, each within " + Number(choice.RowGap, 1) +
        " times the median sample spacing of another (the widest gap near ";
    lines.push_back("the answer is " + std::to_string(choice.Rows) + " " + within +
      PlaceText(choice.RowPlace, choice.Far.Median) + "): rows of one "
      "surface sampled far more finely along them than across (scan lines, a mesh's long rows) "
      "close as curves of their own long before they join; an even spacing across and along "
      "(the rows thinned, or more of them) lets the surface close");
  }
  if (!choice.Joined.empty())
  {
    std::string sizes;
    const std::size_t shown = std::min<std::size_t>(choice.Joined.size(), 4);
    for (std::size_t k = 0; k < shown; ++k)
    {
      sizes += (k == 0 ? "" : k + 1 == shown && shown == choice.Joined.size() ? " and " : ", ") +
        std::to_string(choice.Joined[k]);
    }
    if (shown < choice.Joined.size())
    {
      sizes += ", ...";
    }
    const std::string where = choice.JoinRatio > 0
      ? " (the shortest " + Number(choice.JoinRatio, 1) + " times, near " +
        PlaceText(choice.JoinPlace, choice.Far.Median) + ")"
      : "";
    lines.push_back("the answer's " + std::to_string(choice.Joined.size()) + " parts of " + sizes +
      " samples are held together only by edges over " + Number(choice.Rule.JoinFactor, 0) +
      " times the sample spacing at an end" + where + ": separate closed surfaces a few spacings "
      "apart may have been joined across the gap, or the space between them filled");
  }
  if (choice.NoisyJoin)
  {
    const auto& b = choice.Window.Betti;
    lines.push_back("the answer's " + std::to_string(b[2]) + " voids share " +
      (b[0] == 1 ? std::string("one part") : std::to_string(b[0]) + " parts") +
      ", and the samples are noisy (local flatness at " + std::to_string(flowrecon::FlatnessScales().front().K) +
      " neighbours " + Number(choice.NoiseFlatness, 2) +
      " of a volume sample's): closed surfaces closer than their noise cannot be told "
      "from touching ones, so separate surfaces may have been joined");
  }
  // A resurfaced answer has said which solid lasts longer.
  if (choice.Longest.Length() > choice.Window.Length() && choice.Longest.Betti != choice.Window.Betti &&
    !(choice.Resurfaced && choice.Longest.Betti == choice.Solid.Betti))
  {
    lines.push_back("the Betti numbers " + Betti(choice.Longest) + " hold longer, for t_r in " +
      Window(choice.Longest) + ": a coarser shape (filled or joined) may be meant");
  }
  return lines;
}

std::vector<std::string> PersistenceChoiceWarnings(
  const ThresholdChoice& choice, const std::vector<double>& tps, bool trChosen)
{
  std::vector<std::string> lines;
  for (std::size_t k = 0; k < choice.Best.size(); ++k)
  {
    const StableWindow& w = choice.Best[k];
    if (k != choice.Candidate && w.Length() > 0 && w.Betti != choice.Window.Betti)
    {
      lines.push_back("with t_p " + Short(tps.at(k)) + " the " +
        (trChosen ? "most stable " : "") + "Betti numbers are " + Betti(w) + " (t_r in " +
        Window(w) + "): the simplification changes the answer");
    }
  }
  return lines;
}

std::vector<std::string> ChoiceWarnings(const ThresholdChoice& choice,
  const std::vector<double>& tps, bool trChosen, bool tpChosen)
{
  std::vector<std::string> lines;
  if (trChosen)
  {
    lines = ReconstructionChoiceWarnings(choice);
  }
  if (tpChosen)
  {
    for (std::string& line : PersistenceChoiceWarnings(choice, tps, trChosen))
    {
      lines.push_back(std::move(line));
    }
  }
  return lines;
}

std::string TopologyLine(vtkUnstructuredGrid* grid, vtkTable* topology,
  vtkPolyData* undersampling, double t, double limit, const std::string& why,
  const std::vector<TopologyStep>* profile)
{
  const std::vector<TopologyStep> read = profile ? std::vector<TopologyStep>() : TopologyRows(topology);
  const std::vector<TopologyStep>& rows = profile ? *profile : read;
  vtkFieldData* field = grid->GetFieldData();
  // At t from the profile (a file's cells may go above t_r), else the grid's.
  std::array<long long, 3> betti;
  if (!BettiNumbersAt(rows, t, betti))
  {
    vtkDataArray* b = field->GetArray(names::BettiNumbers);
    if (!b || b->GetNumberOfTuples() < 3)
    {
      return "t_r " + Number(t, 3) + ": no Betti numbers" + why;
    }
    for (vtkIdType d = 0; d < 3; ++d)
    {
      betti[d] = static_cast<long long>(b->GetComponent(d, 0));
    }
  }
  auto value = [field](const char* name, vtkIdType k, double otherwise) {
    vtkDataArray* a = field->GetArray(name);
    return a && a->GetNumberOfTuples() > k ? a->GetComponent(k, 0) : otherwise;
  };
  std::string line = "Betti numbers";
  for (const long long b : betti)
  {
    line += " " + std::to_string(b);
  }
  line += " at t_r " + Number(t, 3) +
    (value(names::ThresholdsChosen, 0, 0) != 0 ? " (auto)" : "");
  if (field->GetArray(names::UsedPersistenceThreshold))
  {
    line += ", t_p " + Short(value(names::UsedPersistenceThreshold, 0, 0)) +
      (value(names::ThresholdsChosen, 1, 0) != 0 ? " (auto)" : "");
  }
  // Where these Betti numbers hold: the chosen window, or the profile's.
  StableWindow around;
  if (vtkDataArray* w = field->GetArray(names::StableWindow))
  {
    if (w->GetNumberOfTuples() == 2 && w->GetComponent(0, 0) < t && t <= w->GetComponent(1, 0))
    {
      around.From = w->GetComponent(0, 0);
      around.To = w->GetComponent(1, 0);
    }
  }
  if (around.Length() == 0)
  {
    around = StableWindowAt(rows, 1, limit, t);
  }
  if (around.Length() > 0)
  {
    // Nothing is known above the limit (Maximum Threshold). No brackets:
    // ParaView 5.11's text display draws "]" as ")".
    line += "; unchanged for " + Number(around.From, 2) + " < t_r" +
      (around.To >= 1e308 ? std::string("") : " <= " + Number(around.To, 2)) +
      (around.To >= limit && limit < 1e308 ? " (as far as computed)" : "");
  }
  std::size_t warnings = UnderSampledPlaces(undersampling).size();
  if (auto* lines = vtkStringArray::SafeDownCast(field->GetAbstractArray(names::ThresholdWarnings)))
  {
    warnings += static_cast<std::size_t>(lines->GetNumberOfValues());
  }
  return line + "; " + std::to_string(warnings) + (warnings == 1 ? " warning" : " warnings");
}

long long StepsBelow(vtkTable* profile, double t)
{
  const vtkIdType steps = profile->GetNumberOfRows();
  vtkDataArray* threshold = steps > 0 ? Column(profile, names::Threshold, "profile") : nullptr;
  vtkIdType kept = 0;
  while (kept < steps && threshold->GetComponent(kept, 0) < t)
  {
    ++kept;
  }
  return kept;
}

std::vector<ProfileJumpNode> LargestProfileJumps(vtkTable* profile, std::size_t count)
{
  const vtkIdType steps = profile->GetNumberOfRows();
  if (steps == 0)
  {
    return {};
  }
  vtkDataArray* threshold = Column(profile, names::Threshold, "profile");
  vtkDataArray* node = Column(profile, names::NodeId, "profile");
  vtkDataArray* index = Column(profile, names::Index, "profile");
  std::vector<double> thresholds(static_cast<std::size_t>(steps));
  for (vtkIdType r = 0; r < steps; ++r)
  {
    thresholds[r] = threshold->GetComponent(r, 0);
  }
  std::vector<ProfileJumpNode> jumps;
  for (const ProfileJump& jump : LargestJumps(thresholds, count))
  {
    const auto r = static_cast<vtkIdType>(jump.Step);
    jumps.push_back({ jump, static_cast<Id>(node->GetComponent(r, 0)),
      static_cast<int>(index->GetComponent(r, 0)) });
  }
  return jumps;
}

std::vector<UnderSampledPlace> UnderSampledPlaces(vtkPolyData* warnings)
{
  const vtkIdType n = warnings ? warnings->GetNumberOfPoints() : 0;
  vtkPointData* pd = n > 0 ? warnings->GetPointData() : nullptr;
  vtkDataArray* threshold = pd ? pd->GetArray(names::Threshold) : nullptr;
  vtkDataArray* dimension = pd ? pd->GetArray(names::Dimension) : nullptr;
  vtkDataArray* change = pd ? pd->GetArray(names::Change) : nullptr;
  vtkDataArray* spacing = pd ? pd->GetArray(names::Spacing) : nullptr;
  vtkDataArray* node = pd ? pd->GetArray(names::NodeId) : nullptr;
  std::vector<UnderSampledPlace> places;
  if (!threshold || !dimension || !change || !spacing || !node)
  {
    return places;
  }
  // (t_r, node, dimension, appears) -> its place.
  std::map<std::tuple<double, Id, int, bool>, std::size_t> seen;
  for (vtkIdType i = 0; i < n; ++i)
  {
    UnderSampledPlace place;
    place.Threshold = threshold->GetComponent(i, 0);
    place.Node = static_cast<Id>(node->GetComponent(i, 0));
    place.Dimension = std::max(0, std::min(3, static_cast<int>(dimension->GetComponent(i, 0))));
    place.Appears = change->GetComponent(i, 0) > 0;
    const auto key = std::make_tuple(place.Threshold, place.Node,
      static_cast<int>(dimension->GetComponent(i, 0)), place.Appears);
    const auto it = seen.find(key);
    if (it != seen.end())
    {
      ++places[it->second].Count;
      continue;
    }
    warnings->GetPoint(i, place.Location.data());
    place.Spacing = spacing->GetComponent(i, 0);
    place.Count = 1;
    seen.emplace(key, places.size());
    places.push_back(place);
  }
  return places;
}

std::string Describe(const UnderSampledPlace& place)
{
  static const char* const one[2][4] = { { "parts join", "hole closes", "void fills",
                                           "cavity fills" },
    { "part appears", "hole opens", "void closes in", "cavity closes in" } };
  static const char* const many[2][4] = { { "parts join", "holes close", "voids fill",
                                            "cavities fill" },
    { "parts appear", "holes open", "voids close in", "cavities close in" } };
  const int up = place.Appears ? 1 : 0;
  const int d = place.Dimension;
  std::ostringstream os;
  os << "under-sampled near " << PlaceText(place.Location, place.Spacing / 10) << ": spacing "
     << place.Spacing << "; at t_r " << place.Threshold << " ";
  if (place.Count == 1)
  {
    os << (d == 0 && up == 0 ? "" : "a ") << one[up][d];
  }
  else
  {
    os << place.Count << " " << many[up][d];
  }
  return os.str();
}

std::string PlaceText(const std::array<double, 3>& x, double resolution)
{
  const double far = std::max({ std::fabs(x[0]), std::fabs(x[1]), std::fabs(x[2]) });
  int digits = 6;
  if (far > 0 && resolution > 0 && std::isfinite(far) && std::isfinite(resolution))
  {
    digits = std::clamp(static_cast<int>(std::ceil(std::log10(far / resolution))) + 1, 6, 17);
  }
  std::ostringstream os;
  os << std::setprecision(digits) << "(" << x[0] << ", " << x[1] << ", " << x[2] << ")";
  return os.str();
}

} // namespace flowrecon
