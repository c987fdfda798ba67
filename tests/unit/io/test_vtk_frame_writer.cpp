#include "io/vtk_frame_writer.hpp"
#include "support/test_folder.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkIdList.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLMultiBlockDataReader.h>

namespace {

using namespace grainload;
using namespace grainload::io;

Frame sample_frame(double time) {
    Block sand{"sand", Block::Kind::particles, {}, {}, {}, {}};
    sand.points = {Vec3(0, 0, 0), Vec3(1, 2, 3), Vec3(-1, 0.5, 2)};
    sand.point_arrays.push_back({"density", 1, {2099.0, 2100.5, 2098.25}});
    sand.point_arrays.push_back({"velocity", 3, {1, 2, 3, 4, 5, 6, 7, 8, 9}});
    FieldArray stress{"stress", 6, {}};
    for (int i = 0; i < 18; ++i) {
        stress.values.push_back(1e6 * i + time);
    }
    sand.point_arrays.push_back(stress);
    Block wall{"wall", Block::Kind::shell, {}, {}, {}, {}};
    wall.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(2, 0, 0)};
    wall.cells = {{0, 1, 2, 3}, {1, 4, 2, -1}};
    wall.point_arrays.push_back({"displacement", 3, std::vector<double>(15, time)});
    wall.cell_arrays.push_back({"thickness", 1, {0.01, 0.02}});
    Block contacts{"contacts", Block::Kind::lines, {}, {}, {}, {}};
    contacts.points = {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1)};
    contacts.cells = {{0, 1, -1, -1}, {2, 3, -1, -1}};
    contacts.cell_arrays.push_back({"force", 3, {0, 0, time, 1, 2, 3}});
    return Frame{time, {sand, wall, contacts}};
}

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Values go through VTK's writer and reader as binary doubles, so they must come back exactly.
void expect_array(vtkDataSetAttributes* data, const FieldArray& field) {
    vtkDataArray* array = data->GetArray(field.name.c_str());
    ASSERT_NE(array, nullptr) << field.name;
    ASSERT_EQ(array->GetNumberOfComponents(), field.components) << field.name;
    const auto count = array->GetNumberOfTuples() * field.components;
    ASSERT_EQ(static_cast<std::size_t>(count), field.values.size()) << field.name;
    for (vtkIdType k = 0; k < count; ++k) {
        EXPECT_EQ(array->GetComponent(k / field.components, static_cast<int>(k % field.components)),
                  field.values[static_cast<std::size_t>(k)])
            << field.name << '[' << k << ']';
    }
}

TEST(VtkFrameWriter, FramesReadBackWithVtkReadersUnchanged) {
    const std::string directory = grainload::testing::process_folder() + "grainload_vtk_writer";
    std::filesystem::remove_all(directory);
    VtkFrameWriter writer(directory, "demo");
    writer.write(sample_frame(0.0));
    const Frame expected = sample_frame(0.125);
    const std::string vtm = writer.write(expected);

    vtkNew<vtkXMLMultiBlockDataReader> reader;
    reader->SetFileName(vtm.c_str());
    reader->Update();
    auto* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
    ASSERT_NE(blocks, nullptr);
    ASSERT_EQ(blocks->GetNumberOfBlocks(), 3u);
    for (unsigned b = 0; b < 3; ++b) {
        auto* data = vtkDataSet::SafeDownCast(blocks->GetBlock(b));
        ASSERT_NE(data, nullptr);
        const Block& block = expected.blocks[b];
        ASSERT_EQ(data->GetNumberOfPoints(), static_cast<vtkIdType>(block.points.size()));
        for (std::size_t i = 0; i < block.points.size(); ++i) {
            double x[3];
            data->GetPoint(static_cast<vtkIdType>(i), x);
            EXPECT_EQ(Vec3(x[0], x[1], x[2]), block.points[i]);
        }
        for (const auto& field : block.point_arrays) {
            expect_array(data->GetPointData(), field);
        }
        for (const auto& field : block.cell_arrays) {
            expect_array(data->GetCellData(), field);
        }
    }
    EXPECT_EQ(vtkDataSet::SafeDownCast(blocks->GetBlock(1))->GetNumberOfCells(), 2);
    // The contacts' block holds two lines, each between its two points.
    auto* lines = vtkDataSet::SafeDownCast(blocks->GetBlock(2));
    ASSERT_EQ(lines->GetNumberOfCells(), 2);
    for (vtkIdType c = 0; c < 2; ++c) {
        EXPECT_EQ(lines->GetCellType(c), VTK_LINE);
        vtkNew<vtkIdList> ends;
        lines->GetCellPoints(c, ends);
        ASSERT_EQ(ends->GetNumberOfIds(), 2);
        EXPECT_EQ(ends->GetId(0), 2 * c);
        EXPECT_EQ(ends->GetId(1), 2 * c + 1);
    }

    const std::string pvd = read_text(directory + "/demo.pvd");
    EXPECT_NE(pvd.find("timestep=\"0\" file=\"frames/demo_000000.vtm\""), std::string::npos);
    EXPECT_NE(pvd.find("timestep=\"0.125\" file=\"frames/demo_000001.vtm\""), std::string::npos);
    for (const auto& entry : std::filesystem::recursive_directory_iterator(directory)) {
        EXPECT_NE(entry.path().extension(), ".tmp") << "left behind: " << entry.path();
    }
}

} // namespace
