// The bad-input table: every module, every class of bad input (README "Reliability").
// Placeholders: {d} the case's folder; fixtures copied into it before the run:
//   {ct} {points} CT and control points (Resources/SampleData/cthead.*)
//   {atlas} {landmarks} {skin} {skull} the atlas mesh, its landmarks and surfaces (Resources/Atlas)
//   {field} a 2x2x2 zero displacement field; {nan} a float CT with one NaN voxel
//   {big} a 4 kB NRRD whose header declares 2048^3 voxels; {bigvtu} {bigvtp} VTK XML files declaring
//   10^11 points; {dicomjunk} a folder holding junk files only; {cropped} the CT cut below the lips;
//   {truncnrrd} {truncmha} {truncnii} {truncniigz} headsq cut to half its length in each format;
//   {badtype} a MetaImage of an unknown ElementType; {nanatlas} the atlas with a NaN landmark;
//   {truncvtp} the atlas skin cut to half its length; {noxyz} a PLY declaring no y and z.
// `earlier` names outputs of an earlier run made before the case ("x/" a folder with a file in it):
// they, like the inputs, must be byte-identical afterwards and nothing may be added.
#pragma once

#include <string>
#include <vector>

namespace mmrep::testing
{

struct BadInputCase
{
  std::string name;   // test name: <Class>_<Module>[_what]
  std::string module;
  std::vector<std::string> args;
  int exitCode;        // 2: refused from the command line, 1: refused by the module
  std::string culprit; // the one stderr line must contain this
  std::vector<std::string> earlier = {};
  bool display = false;           // renders pictures: run under xvfb-run without a display
  long long addressSpaceKiB = 0;  // ulimit -v for the run, 0 for none
};

inline std::vector<BadInputCase> BadInputCases()
{
  const std::vector<std::string> air = {"{atlas}", "{skin}", "{skull}", "{landmarks}"}; // AtlasRegistration inputs
  auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const long long twoGiB = 2097152;
  return {
    // An output that is an input (or holds it): refused before any work, the input intact.
    {"OutputIsInput_AtlasRegistration", "AtlasRegistration", with(air, {"{atlas}"}), 2, "outputMesh"},
    {"OutputIsInput_BuildFaceAtlas", "BuildFaceAtlas", {"{ct}", "{ct}"}, 2, "outputMesh"},
    {"OutputIsInput_DistanceMap", "DistanceMap", {"{skin}", "{skin}"}, 2, "outputMap"},
    {"OutputIsInput_FaceModelPipeline_folderHoldingInputs", "FaceModelPipeline",
     {"{ct}", "{points}", "--outputDirectory", "{d}", "--noPictures"}, 2, "outputDirectory"},
    {"OutputIsInput_FaceModelPipeline_insideInputFolder", "FaceModelPipeline",
     {"{dicomjunk}", "{points}", "--outputDirectory", "{dicomjunk}/speaker", "--noPictures"}, 2, "outputDirectory"},
    {"OutputIsInput_LocalRefinement", "LocalRefinement", {"{atlas}", "{skin}", "{atlas}"}, 2, "outputMesh"},
    {"OutputIsInput_MeshConvert", "MeshConvert", {"{atlas}", "{atlas}"}, 2, "outputMesh"},
    {"OutputIsInput_MeshQuality", "MeshQuality", {"{atlas}", "--outputMesh", "{atlas}"}, 2, "outputMesh"},
    {"OutputIsInput_MeshQuality_returnFile", "MeshQuality", {"{atlas}", "--returnparameterfile", "{atlas}"}, 2,
     "return parameter file"},
    {"OutputIsInput_MeshReparation", "MeshReparation", {"{atlas}", "{d}/out.vtu", "--report", "{atlas}"}, 2,
     "report", {"out.vtu"}},
    {"OutputIsInput_MuscleInference", "MuscleInference", {"{atlas}", "{atlas}", "{field}", "{field}"}, 2,
     "outputMesh"},
    {"OutputIsInput_SimulateMuscleActivation", "SimulateMuscleActivation", {"{atlas}", "{atlas}"}, 2, "outputModel"},
    {"OutputIsInput_SkinSkullSurfaces_maskOverCT", "SkinSkullSurfaces",
     {"{ct}", "{d}/skin.vtp", "{d}/skull.vtp", "--skinMask", "{ct}"}, 2, "skinMask", {"skin.vtp", "skull.vtp"}},
    {"OutputIsInput_SymmetryPlane", "SymmetryPlane", {"{skin}", "--outputPlane", "{skin}"}, 2, "outputPlane"},
    {"OutputIsInput_SyntheticSubject", "SyntheticSubject", {"{ct}", "{ct}"}, 2, "outputVolume"},
    {"OutputIsInput_SyntheticSubject_landmarks", "SyntheticSubject",
     {"{ct}", "{d}/subject.nrrd", "--landmarksIn", "{points}", "--landmarksOut", "{points}"}, 1, "landmarks"},

    // Two outputs with one path.
    {"TwoOutputsOnePath_AtlasRegistration", "AtlasRegistration", with(air, {"{d}/o.vtu", "--report", "{d}/o.vtu"}),
     2, "report", {"o.vtu"}},
    {"TwoOutputsOnePath_BuildFaceAtlas", "BuildFaceAtlas", {"{ct}", "{d}/o.vtu", "--landmarks", "{d}/o.vtu"}, 2,
     "landmarks", {"o.vtu"}},
    {"TwoOutputsOnePath_DistanceMap", "DistanceMap", {"{skin}", "{d}/m.nrrd", "--returnparameterfile", "{d}/m.nrrd"},
     2, "return parameter file", {"m.nrrd"}},
    {"TwoOutputsOnePath_FaceModelPipeline_returnFileInside", "FaceModelPipeline",
     {"{ct}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures", "--returnparameterfile",
      "{d}/speaker/values.txt"},
     2, "outputDirectory", {"speaker/"}},
    {"TwoOutputsOnePath_LocalRefinement", "LocalRefinement", {"{atlas}", "{skin}", "{d}/o.vtu", "--report", "{d}/o.vtu"},
     2, "report", {"o.vtu"}},
    {"TwoOutputsOnePath_MeshConvert", "MeshConvert", {"{atlas}", "{d}/o.vtk", "--returnparameterfile", "{d}/o.vtk"}, 2,
     "return parameter file", {"o.vtk"}},
    {"TwoOutputsOnePath_MeshQuality", "MeshQuality",
     {"{atlas}", "--outputMesh", "{d}/o.vtu", "--returnparameterfile", "{d}/o.vtu"}, 2, "outputMesh", {"o.vtu"}},
    {"TwoOutputsOnePath_MeshReparation", "MeshReparation",
     {"{atlas}", "{d}/o.vtu", "--histogram", "{d}/o.vtu"}, 2, "histogram", {"o.vtu"}},
    {"TwoOutputsOnePath_MuscleInference", "MuscleInference",
     {"{atlas}", "{atlas}", "{field}", "{d}/o.vtu", "--report", "{d}/o.vtu"}, 2, "report", {"o.vtu"}},
    {"TwoOutputsOnePath_SimulateMuscleActivation", "SimulateMuscleActivation",
     {"{atlas}", "{d}/smile.vtu", "--picture", "{d}/smile.vtu"}, 2, "picture", {"smile.vtu"}},
    {"TwoOutputsOnePath_SkinSkullSurfaces", "SkinSkullSurfaces", {"{ct}", "{d}/s.vtp", "{d}/s.vtp"}, 2, "outputSkull",
     {"s.vtp"}},
    {"TwoOutputsOnePath_SymmetryPlane", "SymmetryPlane",
     {"{skin}", "--outputPlane", "{d}/p.mrk.json", "--returnparameterfile", "{d}/p.mrk.json"}, 2, "outputPlane", {"p.mrk.json"}},
    {"TwoOutputsOnePath_SyntheticSubject", "SyntheticSubject", {"{ct}", "{d}/o.nrrd", "--forwardField", "{d}/o.nrrd"},
     2, "forwardField", {"o.nrrd"}},

    // The return-parameter file's folder does not exist: refused before any work, nothing published.
    {"ReturnFileFolderMissing_AtlasRegistration", "AtlasRegistration",
     with(air, {"{d}/o.vtu", "--returnparameterfile", "{d}/missing/r.txt"}), 2, "return parameter file", {"o.vtu"}},
    {"ReturnFileFolderMissing_BuildFaceAtlas", "BuildFaceAtlas",
     {"{ct}", "{d}/o.vtu", "--returnparameterfile", "{d}/missing/r.txt"}, 2, "return parameter file", {"o.vtu"}},
    {"ReturnFileFolderMissing_DistanceMap", "DistanceMap",
     {"{skin}", "{d}/m.nrrd", "--returnparameterfile", "{d}/missing/r.txt"}, 2, "return parameter file", {"m.nrrd"}},
    {"ReturnFileFolderMissing_FaceModelPipeline", "FaceModelPipeline",
     {"{ct}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures", "--returnparameterfile",
      "{d}/missing/r.txt"},
     2, "return parameter file", {"speaker/"}},
    {"ReturnFileFolderMissing_LocalRefinement", "LocalRefinement",
     {"{atlas}", "{skin}", "{d}/o.vtu", "--returnparameterfile", "{d}/missing/r.txt"}, 2, "return parameter file",
     {"o.vtu"}},
    {"ReturnFileFolderMissing_MeshConvert", "MeshConvert",
     {"{atlas}", "{d}/o.vtk", "--returnparameterfile", "{d}/missing/r.txt"}, 2, "return parameter file", {"o.vtk"}},
    {"ReturnFileFolderMissing_MeshQuality", "MeshQuality",
     {"{atlas}", "--outputMesh", "{d}/o.vtu", "--returnparameterfile", "{d}/missing/r.txt"}, 2,
     "return parameter file", {"o.vtu"}},
    {"ReturnFileFolderMissing_MeshReparation", "MeshReparation",
     {"{atlas}", "{d}/o.vtu", "--returnparameterfile", "{d}/missing/r.txt"}, 2, "return parameter file", {"o.vtu"}},
    {"ReturnFileFolderMissing_MuscleInference", "MuscleInference",
     {"{atlas}", "{atlas}", "{field}", "{d}/o.vtu", "--returnparameterfile", "{d}/missing/r.txt"}, 2,
     "return parameter file", {"o.vtu"}},
    {"ReturnFileFolderMissing_SimulateMuscleActivation", "SimulateMuscleActivation",
     {"{atlas}", "{d}/smile.vtu", "--returnparameterfile", "{d}/missing/r.txt"}, 2, "return parameter file",
     {"smile.vtu"}},
    {"ReturnFileFolderMissing_SkinSkullSurfaces", "SkinSkullSurfaces",
     {"{ct}", "{d}/skin.vtp", "{d}/skull.vtp", "--returnparameterfile", "{d}/missing/r.txt"}, 2,
     "return parameter file", {"skin.vtp", "skull.vtp"}},
    {"ReturnFileFolderMissing_SymmetryPlane", "SymmetryPlane",
     {"{skin}", "--outputPlane", "{d}/p.mrk.json", "--returnparameterfile", "{d}/missing/r.txt"}, 2,
     "return parameter file", {"p.mrk.json"}},
    {"ReturnFileFolderMissing_SyntheticSubject", "SyntheticSubject",
     {"{ct}", "{d}/o.nrrd", "--returnparameterfile", "{d}/missing/r.txt"}, 2, "return parameter file", {"o.nrrd"}},

    // An output whose folder does not exist.
    {"OutputFolderMissing_AtlasRegistration", "AtlasRegistration", with(air, {"{d}/missing/o.vtu"}), 2, "outputMesh"},
    {"OutputFolderMissing_BuildFaceAtlas", "BuildFaceAtlas", {"{ct}", "{d}/missing/o.vtu"}, 2, "outputMesh"},
    {"OutputFolderMissing_DistanceMap", "DistanceMap", {"{skin}", "{d}/missing/m.nrrd"}, 2, "outputMap"},
    {"OutputFolderMissing_FaceModelPipeline", "FaceModelPipeline",
     {"{ct}", "{points}", "--outputDirectory", "{ct}/speaker", "--noPictures"}, 1, "cthead.nrrd"},
    {"OutputFolderMissing_LocalRefinement", "LocalRefinement", {"{atlas}", "{skin}", "{d}/missing/o.vtu"}, 2,
     "outputMesh"},
    {"OutputFolderMissing_MeshConvert", "MeshConvert", {"{atlas}", "{d}/missing/o.vtk"}, 2, "outputMesh"},
    {"OutputFolderMissing_MeshQuality", "MeshQuality", {"{atlas}", "--outputMesh", "{d}/missing/o.vtu"}, 1,
     "missing"},
    {"OutputFolderMissing_MeshReparation", "MeshReparation", {"{atlas}", "{d}/missing/o.vtu"}, 2, "outputMesh"},
    {"OutputFolderMissing_MuscleInference", "MuscleInference", {"{atlas}", "{atlas}", "{field}", "{d}/missing/o.vtu"},
     2, "outputMesh"},
    {"OutputFolderMissing_SimulateMuscleActivation", "SimulateMuscleActivation", {"{atlas}", "{d}/missing/s.vtu"}, 2,
     "outputModel"},
    {"OutputFolderMissing_SkinSkullSurfaces", "SkinSkullSurfaces", {"{ct}", "{d}/skin.vtp", "{d}/missing/skull.vtp"},
     2, "outputSkull", {"skin.vtp"}},
    {"OutputFolderMissing_SymmetryPlane", "SymmetryPlane", {"{skin}", "--outputPlane", "{d}/missing/p.mrk.json"}, 1,
     "missing/p.mrk.json"},
    {"OutputFolderMissing_SyntheticSubject", "SyntheticSubject", {"{ct}", "{d}/missing/o.nrrd"}, 2, "outputVolume"},

    // A step failing after the main result was written: nothing is published.
    {"LateFailure_SimulateMuscleActivation_pictureFolderMissing", "SimulateMuscleActivation",
     {"{atlas}", "{d}/smile.vtu", "--muscles", "ZygomaticusMajor_L", "--picture", "{d}/missing/smile.png"}, 1,
     "smile.png", {"smile.vtu"}, true},
    {"LateFailure_SyntheticSubject_landmarksMissing", "SyntheticSubject",
     {"{ct}", "{d}/o.nrrd", "--landmarksIn", "{d}/none.mrk.json", "--landmarksOut", "{d}/l.mrk.json"}, 1,
     "none.mrk.json", {"o.nrrd"}},

    // Numeric parameters out of their declared range: named, refused before any work.
    {"Range_AtlasRegistration", "AtlasRegistration", with(air, {"{d}/o.vtu", "--controlPointWeight", "-5"}), 2,
     "controlPointWeight"},
    {"Range_BuildFaceAtlas", "BuildFaceAtlas", {"{ct}", "{d}/o.vtu", "--meshSize", "0"}, 2, "meshSize"},
    {"Range_DistanceMap", "DistanceMap", {"{skin}", "{d}/m.nrrd", "--spacing", "0"}, 2, "spacing"},
    {"Range_FaceModelPipeline_controlPointWeight", "FaceModelPipeline",
     {"{ct}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures", "--controlPointWeight", "-5"}, 2,
     "controlPointWeight", {"speaker/"}},
    {"Range_FaceModelPipeline_qualityThreshold", "FaceModelPipeline",
     {"{ct}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures", "--qualityThreshold", "0.95"}, 2,
     "qualityThreshold"},
    {"Range_FaceModelPipeline_transformSpacing", "FaceModelPipeline",
     {"{ct}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures", "--transformSpacing", "1e-6"}, 2,
     "transformSpacing"},
    {"Range_FaceModelPipeline_mapSpacing", "FaceModelPipeline",
     {"{ct}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures", "--mapSpacing", "1e-6"}, 2,
     "mapSpacing"},
    {"Range_FaceModelPipeline_skinThreshold", "FaceModelPipeline",
     {"{ct}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures", "--skinThreshold", "1e9"}, 2,
     "skinThreshold"},
    {"Range_LocalRefinement", "LocalRefinement", {"{atlas}", "{skin}", "{d}/o.vtu", "--spacing", "0.01"}, 2,
     "spacing"},
    {"Range_MeshQuality", "MeshQuality", {"{atlas}", "--threshold", "2"}, 2, "threshold"},
    {"Range_MeshReparation", "MeshReparation", {"{atlas}", "{d}/o.vtu", "--maximumSweeps", "0"}, 2, "maximumSweeps"},
    {"Range_SimulateMuscleActivation", "SimulateMuscleActivation", {"{atlas}", "{d}/s.vtu", "--c10", "-1"}, 2, "c10"},
    {"Range_SimulateMuscleActivation_activations", "SimulateMuscleActivation",
     {"{atlas}", "{d}/s.vtu", "--activations", "1.5"}, 2, "activations"},
    {"Range_SimulateMuscleActivation_forceScale", "SimulateMuscleActivation",
     {"{atlas}", "{d}/s.vtu", "--muscles", "ZygomaticusMajor_L", "--forceScale", "0"}, 2, "forceScale"},
    {"Range_SkinSkullSurfaces", "SkinSkullSurfaces", {"{ct}", "{d}/skin.vtp", "{d}/skull.vtp", "--openingRadius", "-1"},
     2, "openingRadius"},
    {"Range_SymmetryPlane", "SymmetryPlane", {"{skin}", "--trimFraction", "0.9"}, 2, "trimFraction"},
    {"Range_SyntheticSubject", "SyntheticSubject", {"{ct}", "{d}/o.nrrd", "--roll", "90"}, 2, "roll"},
    {"Range_SyntheticSubject_translation", "SyntheticSubject", {"{ct}", "{d}/o.nrrd", "--translation", "1e9,0,0"}, 2,
     "translation"},

    // Sizes derived from parameters: refused before the work, in checked arithmetic.
    {"DerivedSize_DistanceMap", "DistanceMap", {"{skin}", "{d}/m.nrrd", "--spacing", "0.05", "--margin", "500"}, 1,
     "spacing 0.05"},
    {"DerivedSize_AtlasRegistration_transformSpacing", "AtlasRegistration",
     with(air, {"{d}/o.vtu", "--outputTransform", "{d}/t.nrrd", "--transformSpacing", "0.25"}), 1, "--transformSpacing",
     {}, false, twoGiB},
    {"DerivedSize_AtlasRegistration_mapSpacing", "AtlasRegistration", with(air, {"{d}/o.vtu", "--mapSpacing", "0.25"}),
     1, "--mapSpacing 0.25: the distance map over"},
    {"DerivedSize_FaceModelPipeline_mapSpacing", "FaceModelPipeline",
     {"{ct}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures", "--mapSpacing", "0.25"}, 1,
     "--mapSpacing 0.25: the distance map over", {"speaker/"}},
    {"DerivedSize_FaceModelPipeline_transformSpacing", "FaceModelPipeline",
     {"{ct}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures", "--transformSpacing", "0.25"}, 1,
     "--transformSpacing", {"speaker/"}, false, twoGiB},

    // Volumes whose header declares more than memory allows (2048^3 in a 4 kB file), under ulimit -v 2 GiB.
    {"HeaderBudget_BuildFaceAtlas", "BuildFaceAtlas", {"{big}", "{d}/o.vtu"}, 1, "big.nrrd", {}, false, twoGiB},
    {"HeaderBudget_DistanceMap", "DistanceMap", {"{big}", "{d}/m.nrrd"}, 1, "big.nrrd", {}, false, twoGiB},
    {"HeaderBudget_FaceModelPipeline", "FaceModelPipeline",
     {"{big}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures"}, 1, "big.nrrd", {"speaker/"}, false,
     twoGiB},
    {"HeaderBudget_SkinSkullSurfaces", "SkinSkullSurfaces", {"{big}", "{d}/skin.vtp", "{d}/skull.vtp"}, 1, "big.nrrd",
     {}, false, twoGiB},
    {"HeaderBudget_SyntheticSubject", "SyntheticSubject", {"{big}", "{d}/o.nrrd"}, 1, "big.nrrd", {}, false, twoGiB},
    // Meshes and surfaces declaring 10^11 points.
    {"HeaderBudget_AtlasRegistration", "AtlasRegistration",
     {"{bigvtu}", "{skin}", "{skull}", "{landmarks}", "{d}/o.vtu"}, 1, "bigvtu.vtu"},
    {"HeaderBudget_AtlasRegistration_surface", "AtlasRegistration",
     {"{atlas}", "{bigvtp}", "{skull}", "{landmarks}", "{d}/o.vtu"}, 1, "bigvtp.vtp"},
    {"HeaderBudget_DistanceMap_surface", "DistanceMap", {"{bigvtp}", "{d}/m.nrrd"}, 1, "bigvtp.vtp"},
    {"HeaderBudget_FaceModelPipeline_atlas", "FaceModelPipeline",
     {"{ct}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures", "--atlas", "{bigvtu}"}, 1, "bigvtu.vtu",
     {"speaker/"}},
    {"HeaderBudget_LocalRefinement", "LocalRefinement", {"{bigvtu}", "{skin}", "{d}/o.vtu"}, 1, "bigvtu.vtu"},
    {"HeaderBudget_MeshConvert", "MeshConvert", {"{bigvtu}", "{d}/o.vtk"}, 1, "bigvtu.vtu"},
    {"HeaderBudget_MeshQuality", "MeshQuality", {"{bigvtu}"}, 1, "bigvtu.vtu"},
    {"HeaderBudget_MeshReparation", "MeshReparation", {"{bigvtu}", "{d}/o.vtu"}, 1, "bigvtu.vtu"},
    {"HeaderBudget_MuscleInference", "MuscleInference", {"{atlas}", "{bigvtu}", "{field}", "{d}/o.vtu"}, 1,
     "bigvtu.vtu"},
    {"HeaderBudget_SimulateMuscleActivation", "SimulateMuscleActivation", {"{bigvtu}", "{d}/s.vtu"}, 1, "bigvtu.vtu"},
    {"HeaderBudget_SymmetryPlane", "SymmetryPlane", {"{bigvtp}"}, 1, "bigvtp.vtp"},

    // NaN voxels.
    {"NonFinite_BuildFaceAtlas", "BuildFaceAtlas", {"{nan}", "{d}/o.vtu"}, 1, "NaN"},
    {"NonFinite_DistanceMap", "DistanceMap", {"{nan}", "{d}/m.nrrd"}, 1, "NaN"},
    {"NonFinite_FaceModelPipeline", "FaceModelPipeline",
     {"{nan}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures"}, 1, "NaN", {"speaker/"}},
    {"NonFinite_SkinSkullSurfaces", "SkinSkullSurfaces", {"{nan}", "{d}/skin.vtp", "{d}/skull.vtp"}, 1, "NaN"},
    {"NonFinite_SyntheticSubject", "SyntheticSubject", {"{nan}", "{d}/o.nrrd"}, 1, "NaN"},

    // Junk in a DICOM folder: our line, not GDCM's dump.
    {"DicomJunk_BuildFaceAtlas", "BuildFaceAtlas", {"{dicomjunk}", "{d}/o.vtu"}, 1, "dicomjunk"},
    {"DicomJunk_FaceModelPipeline", "FaceModelPipeline",
     {"{dicomjunk}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures"}, 1, "dicomjunk", {"speaker/"}},
    {"DicomJunk_SkinSkullSurfaces", "SkinSkullSurfaces", {"{dicomjunk}", "{d}/skin.vtp", "{d}/skull.vtp"}, 1,
     "dicomjunk"},
    {"DicomJunk_SyntheticSubject", "SyntheticSubject", {"{dicomjunk}", "{d}/o.nrrd"}, 1, "dicomjunk"},

    // Damaged files: the toolkit's error in words (no addresses, no class names), the file named.
    {"Damaged_SkinSkullSurfaces_truncatedNrrd", "SkinSkullSurfaces", {"{truncnrrd}", "{d}/skin.vtp", "{d}/skull.vtp"}, 1,
     "truncated.nrrd': cannot read voxel data"},
    {"Damaged_SkinSkullSurfaces_truncatedMha", "SkinSkullSurfaces", {"{truncmha}", "{d}/skin.vtp", "{d}/skull.vtp"}, 1,
     "truncated.mha': cannot read voxel data"},
    {"Damaged_SkinSkullSurfaces_truncatedNii", "SkinSkullSurfaces", {"{truncnii}", "{d}/skin.vtp", "{d}/skull.vtp"}, 1,
     "truncated.nii': truncated file"},
    {"Damaged_FaceModelPipeline_truncatedNiiGz", "FaceModelPipeline",
     {"{truncniigz}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures"}, 1,
     "truncated.nii.gz': truncated or corrupt compressed data", {"speaker/"}},
    {"Damaged_SyntheticSubject_unknownVoxelType", "SyntheticSubject", {"{badtype}", "{d}/o.nrrd"}, 1,
     "badtype.mha': unknown voxel type"},
    {"Damaged_DistanceMap_truncatedVtp", "DistanceMap", {"{truncvtp}", "{d}/m.nrrd"}, 1, "truncated.vtp': cannot read"},
    {"Damaged_SymmetryPlane_plyWithoutCoordinates", "SymmetryPlane", {"{noxyz}"}, 1, "noxyz.ply': the PLY header"},

    // Non-finite atlas landmarks are blamed on the atlas, not on the control points.
    {"NonFinite_AtlasRegistration_atlasLandmark", "AtlasRegistration",
     {"{nanatlas}", "{skin}", "{skull}", "{landmarks}", "{d}/o.vtu"}, 1, "nanatlas.vtu: landmark 'LeftEyeOuterCorner'"},
    {"NonFinite_FaceModelPipeline_atlasLandmark", "FaceModelPipeline",
     {"{ct}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures", "--atlas", "{nanatlas}"}, 1,
     "nanatlas.vtu: landmark 'LeftEyeOuterCorner'", {"speaker/"}},

    // Field of view: a CT cut below the lips has no chin; an earlier result stays as it was.
    {"FieldOfView_FaceModelPipeline_noChin", "FaceModelPipeline",
     {"{cropped}", "{points}", "--outputDirectory", "{d}/speaker", "--noPictures"}, 1, "chin by", {"speaker/"}},
  };
}

} // namespace mmrep::testing
