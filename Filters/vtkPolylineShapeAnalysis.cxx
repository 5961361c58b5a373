#include "vtkPolylineShapeAnalysis.h"

#include "ArrayNames.h"
#include "LineCells.h"
#include "OutputArrays.h"
#include "ShapeAnalysis.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace names = shapesplines::names;

vtkStandardNewMacro(vtkPolylineShapeAnalysis);

namespace
{
using shapesplines::Vec3;

template <typename Array>
vtkSmartPointer<Array> NewZeroArray(const char* name, int components, vtkIdType tuples)
{
  auto array = shapesplines::newArray<Array>(name, components, tuples);
  array->Fill(0);
  return array;
}

Vec3 TupleOf(vtkDataArray* array, vtkIdType id)
{
  Vec3 v;
  array->GetTuple(id, v.data());
  return v;
}

/// The point arrays the audit reads and their components.
constexpr std::array<std::pair<const char*, int>, 5> CurveArrays = { { { names::SpanIndex, 1 },
  { names::Tangent, 3 }, { names::Binormal, 3 }, { names::Curvature, 1 }, { names::Torsion, 1 } } };

/// Whether curve has the point arrays the audit reads, a tuple per point each.
bool HasCurveArrays(vtkPolyData* curve)
{
  return std::all_of(CurveArrays.begin(), CurveArrays.end(), [&](const auto& wanted) {
    vtkDataArray* array = curve->GetPointData()->GetArray(wanted.first);
    return array && array->GetNumberOfComponents() == wanted.second &&
      array->GetNumberOfTuples() == curve->GetNumberOfPoints();
  });
}

/// The curve's samples of one line, for the audit (see HasCurveArrays).
std::vector<shapesplines::AuditSample> CurveSamples(
  vtkPolyData* curve, const std::vector<vtkIdType>& ids, bool& closed)
{
  vtkPointData* pd = curve->GetPointData();
  vtkDataArray* span = pd->GetArray(names::SpanIndex);
  vtkDataArray* tangent = pd->GetArray(names::Tangent);
  vtkDataArray* binormal = pd->GetArray(names::Binormal);
  vtkDataArray* curvature = pd->GetArray(names::Curvature);
  vtkDataArray* torsion = pd->GetArray(names::Torsion);
  std::vector<shapesplines::AuditSample> samples;
  closed = ids.size() > 1 && ids.front() == ids.back();
  const size_t count = closed ? ids.size() - 1 : ids.size();
  for (size_t k = 0; k < count; ++k)
  {
    shapesplines::AuditSample s;
    s.Span = static_cast<int>(span->GetTuple1(ids[k]));
    s.Frame.Tangent = TupleOf(tangent, ids[k]);
    s.Frame.Binormal = TupleOf(binormal, ids[k]);
    s.Frame.Curvature = curvature->GetTuple1(ids[k]);
    s.Frame.Torsion = torsion->GetTuple1(ids[k]);
    samples.push_back(s);
  }
  shapesplines::markKnots(samples, closed);
  return samples;
}

/// The discrete shape of the data, per input point (0 off the lines).
struct DiscreteShapeArrays
{
  explicit DiscreteShapeArrays(vtkIdType points)
    : Curvature(NewZeroArray<vtkDoubleArray>(names::DiscreteCurvature, 1, points))
    , Torsion(NewZeroArray<vtkDoubleArray>(names::DiscreteTorsion, 1, points))
    , Binormal(NewZeroArray<vtkDoubleArray>(names::DiscreteBinormal, 3, points))
    , Collinear(NewZeroArray<vtkUnsignedCharArray>(names::Collinear, 1, points))
    , Convex(NewZeroArray<vtkUnsignedCharArray>(names::Convex, 1, points))
    , Coplanar(NewZeroArray<vtkUnsignedCharArray>(names::Coplanar, 1, points))
  {
  }

  /// One line's point ids, of which its cleaned data kept those at SourceIndex.
  void Write(const std::vector<vtkIdType>& ids, const shapesplines::CleanPolyline& data,
    const shapesplines::DiscreteShape& shape)
  {
    // Dropped repeats take the values of the point they repeat.
    for (size_t i = 0, kept = 0; i < ids.size(); ++i)
    {
      while (
        kept + 1 < data.SourceIndex.size() && data.SourceIndex[kept + 1] <= static_cast<int>(i))
      {
        ++kept;
      }
      if (data.SourceIndex.empty())
      {
        break;
      }
      this->Curvature->SetValue(ids[i], shape.Curvature[kept]);
      this->Binormal->SetTuple(ids[i], shape.Binormal[kept].data());
      this->Collinear->SetValue(ids[i], shape.Collinear[kept]);
      this->Convex->SetValue(ids[i], shape.Convex[kept]);
      if (kept < shape.Torsion.size())
      {
        this->Torsion->SetValue(ids[i], shape.Torsion[kept]);
        this->Coplanar->SetValue(ids[i], shape.Coplanar[kept]);
      }
    }
  }

  void AddTo(vtkPointData* pointData) const
  {
    shapesplines::addArrays(
      pointData, { this->Curvature, this->Torsion, this->Binormal, this->Collinear, this->Convex,
                   this->Coplanar });
  }

  vtkSmartPointer<vtkDoubleArray> Curvature, Torsion, Binormal;
  vtkSmartPointer<vtkUnsignedCharArray> Collinear, Convex, Coplanar;
};

/// The audit's results: ViolationMask per point, counts per line.
struct AuditArrays
{
  static constexpr int Criteria = static_cast<int>(shapesplines::ShapeCriterion::Count);

  explicit AuditArrays(vtkIdType points)
    : Mask(NewZeroArray<vtkIntArray>(names::ViolationMask, 1, points))
    , Total(NewZeroArray<vtkIntArray>(names::ShapeViolations, 1, 0))
    , Preserving(NewZeroArray<vtkUnsignedCharArray>(names::ShapePreserving, 1, 0))
  {
    static_assert(names::CriterionViolations.size() == Criteria, "a count per criterion");
    for (int c = 0; c < Criteria; ++c)
    {
      this->Counts[c] = NewZeroArray<vtkIntArray>(names::CriterionViolations[c], 1, 0);
    }
  }

  /// The next line's audit (none when it could not be audited), its point
  /// ids and which of them its cleaned data kept.
  void AddLine(const std::optional<shapesplines::ShapeAudit>& result,
    const std::vector<vtkIdType>& ids, const std::vector<int>& sourceIndex)
  {
    for (size_t j = 0; result && j < result->SpanMask.size(); ++j)
    {
      this->Mask->SetValue(ids[sourceIndex[j]], static_cast<int>(result->SpanMask[j]));
    }
    // A line that could not be audited must not read as shape-preserving.
    this->Total->InsertNextValue(result ? result->violations() : -1);
    this->Preserving->InsertNextValue(result && result->preserving() ? 1 : 0);
    for (int c = 0; c < Criteria; ++c)
    {
      this->Counts[c]->InsertNextValue(result ? result->Failures[c] : -1);
    }
  }

  void AddCountsTo(vtkCellData* cellData) const
  {
    shapesplines::addArrays(cellData, { this->Total, this->Preserving });
    for (const auto& count : this->Counts)
    {
      cellData->AddArray(count);
    }
  }

  vtkSmartPointer<vtkIntArray> Mask, Total;
  vtkSmartPointer<vtkUnsignedCharArray> Preserving;
  std::array<vtkSmartPointer<vtkIntArray>, Criteria> Counts;
};

/// A line's points; false, with the error reported, when the line is damaged
/// or a point is not finite.
bool ReadLinePoints(vtkObject* self, vtkPolyData* input, const shapesplines::LineCell& line,
  std::vector<Vec3>& points)
{
  const auto& ids = line.PointIds;
  points.resize(ids.size());
  bool finite = true;
  for (size_t i = 0; i < ids.size(); ++i)
  {
    input->GetPoint(ids[i], points[i].data());
    finite = finite && points[i].allFinite();
  }
  if (!line.Error.empty())
  {
    vtkErrorWithObjectMacro(
      self, "Line (cell " << line.CellId << ") skipped: " << line.Error << ".");
    return false;
  }
  if (!finite)
  {
    vtkErrorWithObjectMacro(
      self, "Line (cell " << line.CellId << ") skipped: a point is not finite.");
  }
  return finite;
}

/// The audit of one data line against its curve line; none, with a warning,
/// when their spans or closure differ.
std::optional<shapesplines::ShapeAudit> AuditLine(vtkObject* self,
  const shapesplines::LineCell& line, vtkPolyData* curve, const shapesplines::LineCell& curveLine,
  const shapesplines::CleanPolyline& data, const shapesplines::DiscreteShape& shape,
  const shapesplines::ShapeTolerances& tolerances)
{
  bool curveClosed = false;
  const auto samples = CurveSamples(curve, curveLine.PointIds, curveClosed);
  if (samples.back().Span + 1 != data.numberOfSpans() || curveClosed != data.Closed)
  {
    vtkWarningWithObjectMacro(self, "Line (cell " << line.CellId << "): the curve has "
                                    << samples.back().Span + 1 << " spans for "
                                    << data.numberOfSpans()
                                    << " data spans (or differs in closure): not audited.");
    return std::nullopt;
  }
  return shapesplines::auditShape(data, shape, samples, tolerances);
}
} // namespace

vtkPolylineShapeAnalysis::vtkPolylineShapeAnalysis()
{
  this->SetNumberOfInputPorts(2);
}

vtkPolylineShapeAnalysis::~vtkPolylineShapeAnalysis() = default;

int vtkPolylineShapeAnalysis::FillInputPortInformation(int port, vtkInformation* info)
{
  // Composite data are taken whole (not block by block by the pipeline) so
  // that each data block meets the curve's block at the same place.
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObjectTree");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkPolylineShapeAnalysis::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

vtkTypeBool vtkPolylineShapeAnalysis::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    return this->RequestDataObject(inputVector, outputVector);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int vtkPolylineShapeAnalysis::RequestDataObject(
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  if (!input)
  {
    return 0;
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataObject* output = vtkDataObject::GetData(outInfo);
  if (!output || !output->IsA(input->GetClassName()))
  {
    outInfo->Set(vtkDataObject::DATA_OBJECT(), vtk::TakeSmartPointer(input->NewInstance()));
  }
  return 1;
}

int vtkPolylineShapeAnalysis::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* inputObject = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* curveObject = vtkDataObject::GetData(inputVector[1], 0);
  vtkDataObject* outputObject = vtkDataObject::GetData(outputVector, 0);
  if (!inputObject || !outputObject)
  {
    vtkErrorMacro("Missing input or output.");
    return 0;
  }
  if (std::isnan(this->DataShapeTolerance) || std::isnan(this->CurveShapeTolerance))
  {
    vtkErrorMacro("DataShapeTolerance and CurveShapeTolerance must not be NaN: nothing analysed.");
    return 1;
  }
  auto* curveTree = vtkDataObjectTree::SafeDownCast(curveObject);
  if (auto* input = vtkPolyData::SafeDownCast(inputObject))
  {
    vtkPolyData* curve = vtkPolyData::SafeDownCast(curveObject);
    if (curveTree)
    {
      // One data set against a composite curve: its only poly data block.
      auto blocks = vtkCompositeDataSet::GetDataSets<vtkPolyData>(curveTree);
      if (blocks.size() == 1)
      {
        curve = blocks[0];
      }
      else
      {
        vtkErrorMacro("The curve input has " << blocks.size() << " poly data blocks for one data "
                                             << "set: nothing audited.");
        curve = nullptr;
      }
    }
    this->Analyse(input, curve, vtkPolyData::SafeDownCast(outputObject));
    return 1;
  }

  auto* inputTree = vtkDataObjectTree::SafeDownCast(inputObject);
  auto* outputTree = vtkDataObjectTree::SafeDownCast(outputObject);
  if (!inputTree || !outputTree)
  {
    vtkErrorMacro("Input 0 must be poly data or a composite of poly data.");
    return 0;
  }
  this->AnalyseBlocks(inputTree, curveObject, outputTree);
  return 1;
}

void vtkPolylineShapeAnalysis::AnalyseBlocks(
  vtkDataObjectTree* inputTree, vtkDataObject* curveObject, vtkDataObjectTree* outputTree)
{
  auto* curveTree = vtkDataObjectTree::SafeDownCast(curveObject);
  auto* curvePolyData = vtkPolyData::SafeDownCast(curveObject);
  outputTree->CopyStructure(inputTree);
  const size_t dataBlocks = vtkCompositeDataSet::GetDataSets<vtkPolyData>(inputTree).size();
  auto it = vtk::TakeSmartPointer(inputTree->NewTreeIterator());
  it->SkipEmptyNodesOn();
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    vtkDataObject* blockObject = it->GetCurrentDataObject();
    auto* block = vtkPolyData::SafeDownCast(blockObject);
    if (!block)
    {
      vtkWarningMacro("Block " << it->GetCurrentFlatIndex() << " is a "
                               << blockObject->GetClassName() << ", not poly data: left out.");
      continue;
    }
    vtkPolyData* curve = nullptr;
    if (curveTree)
    {
      curve = vtkPolyData::SafeDownCast(curveTree->GetDataSet(it));
      if (!curve)
      {
        vtkErrorMacro("The curve input has no poly data where the data have block "
          << it->GetCurrentFlatIndex() << ": that block is not audited.");
      }
    }
    else if (curvePolyData && dataBlocks == 1)
    {
      curve = curvePolyData;
    }
    else if (curvePolyData)
    {
      vtkErrorMacro("One curve for " << dataBlocks << " data blocks: block "
                                     << it->GetCurrentFlatIndex() << " is not audited (give a "
                                     << "curve of the same blocks, e.g. the spline filter's output).");
    }
    vtkNew<vtkPolyData> analysed;
    this->Analyse(block, curve, analysed);
    outputTree->SetDataSet(it, analysed);
  }
}

void vtkPolylineShapeAnalysis::Analyse(vtkPolyData* input, vtkPolyData* curve, vtkPolyData* output)
{
  output->ShallowCopy(input);
  const vtkIdType nPoints = input->GetNumberOfPoints();
  // A damaged file's arrays (not one tuple per point or cell) are not passed on.
  const std::string points = shapesplines::removeMisfitArrays(output->GetPointData(), nPoints);
  const std::string cells =
    shapesplines::removeMisfitArrays(output->GetCellData(), input->GetNumberOfCells());
  if (!points.empty())
  {
    vtkWarningMacro("Point arrays without one tuple per point are left out of the output: "
      << points << ".");
  }
  if (!cells.empty())
  {
    vtkWarningMacro("Cell arrays without one tuple per cell are left out of the output: "
      << cells << ".");
  }
  DiscreteShapeArrays discrete(nPoints);
  if (input->GetNumberOfLines() == 0)
  {
    vtkWarningMacro("Input has no lines: nothing to analyse.");
  }

  const auto lines = shapesplines::lineCells(input);
  const auto curves = curve ? shapesplines::lineCells(curve) : std::vector<shapesplines::LineCell>{};
  if (curve && curves.size() != lines.size())
  {
    vtkWarningMacro("The curve input has " << curves.size() << " lines for " << lines.size()
                                           << " data lines: lines past the shorter are not audited.");
  }
  const bool audit = curve != nullptr;
  const bool curveReadable = audit && HasCurveArrays(curve);
  if (audit && !curveReadable)
  {
    vtkErrorMacro("The curve input lacks SpanIndex, Tangent, Binormal, Curvature or Torsion "
                  "(one tuple per point, 1, 3, 3, 1 and 1 components): it must be the output of "
                  "a Shape Splines curve filter. Nothing audited (ShapeViolations -1).");
  }
  AuditArrays audits(nPoints);

  shapesplines::ShapeTolerances tolerances;
  tolerances.Data = this->DataShapeTolerance;
  tolerances.Curve = this->CurveShapeTolerance;
  // As the curve filters do: a turn or twist within the rounding of float
  // input, or of coordinates written with few digits, is no shape.
  const double precision = shapesplines::coordinatePrecision(input);
  for (size_t l = 0; l < lines.size(); ++l)
  {
    std::vector<Vec3> points;
    const bool finite = ReadLinePoints(this, input, lines[l], points);
    const auto data = shapesplines::cleanPolyline(points, this->Closed);
    double largest = 0.0; // boundingBox() needs a point; a cell may have none
    for (const Vec3& p : data.Points)
    {
      largest = std::max(largest, p.cwiseAbs().maxCoeff());
    }
    const auto shape =
      shapesplines::discreteShape(data, tolerances, {}, precision * largest,
        shapesplines::coordinateSteps(data.Points, precision));
    if (finite)
    {
      discrete.Write(lines[l].PointIds, data, shape);
    }
    if (!audit)
    {
      continue;
    }
    const shapesplines::LineCell* curveLine = l < curves.size() ? &curves[l] : nullptr;
    std::optional<shapesplines::ShapeAudit> result;
    if (curveLine && !curveLine->Error.empty())
    {
      vtkErrorMacro("Curve line (cell " << curveLine->CellId << ") not audited: "
                                        << curveLine->Error << ".");
    }
    else if (finite && curveReadable && curveLine && data.numberOfSpans() > 0 &&
      !curveLine->PointIds.empty())
    {
      result = AuditLine(this, lines[l], curve, *curveLine, data, shape, tolerances);
    }
    audits.AddLine(result, lines[l].PointIds, data.SourceIndex);
  }

  discrete.AddTo(output->GetPointData());
  if (audit)
  {
    output->GetPointData()->AddArray(audits.Mask);
    // Cell arrays only fit when every cell is a line.
    if (input->GetNumberOfCells() == input->GetNumberOfLines())
    {
      audits.AddCountsTo(output->GetCellData());
    }
    else
    {
      vtkWarningMacro("Input has non-line cells: per-line audit counts are not written.");
    }
  }
}

void vtkPolylineShapeAnalysis::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Closed: " << (this->Closed ? "On" : "Off") << "\n";
  os << indent << "DataShapeTolerance: " << this->DataShapeTolerance << "\n";
  os << indent << "CurveShapeTolerance: " << this->CurveShapeTolerance << "\n";
}
