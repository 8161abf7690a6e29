// Sylva import for Unity (2019.4 and later), an editor script: put this folder's files in
// an `Editor` folder of the project (SylvaWind.shader may go anywhere under Assets).
// What it does, for models exported with `sylva export --profile unity`:
// - FBX (`--format fbx`): Unity's FBX importer already builds a LODGroup from the file's
//   LOD group. This script turns every `<name>_collider_<i>` mesh into a convex
//   MeshCollider (its renderer removed) and gives every material a `<material>_wind.mat`
//   beside the model, on the Sylva/Wind shader with the material's colour.
// - glTF (.glb/.gltf through glTFast or UnityGLTF, which import no LODs): after the import
//   it writes `<file>_sylva.prefab` beside the file: the imported tree with a LODGroup made
//   from the children named `<name>_LOD0`, `<name>_LOD1`, ... (level i takes over below
//   50% / 2^i of the screen height, the last culled below 1%), the same convex
//   MeshColliders and wind materials. Re-importing the file rewrites the prefab.
// Every wind material gets the tree's wind (_WindStrength, _WindDirection,
// _WindGustFrequency, _WindFlutter) from the export's `sylva_wind_*` values: the FBX mesh
// nodes' user properties (OnPostprocessGameObjectWithUserProperties), the glb materials'
// extras (read from the file, which glTF importers do not keep). A material without them
// keeps the shader's defaults.
// The unity profile writes the wind into TEXCOORD_1/2 with v flipped, because Unity's glTF
// importers flip v on every UV set; Unity's FBX importer flips nothing and the FBX carries
// the wind unflipped; either way the mesh's uv2 = (sway, flex), uv3 = (phase, flutter), as
// SylvaWind.shader reads them.
using System;
using System.Collections.Generic;
using System.IO;
using System.Text;
using System.Text.RegularExpressions;
using UnityEditor;
using UnityEngine;

public class SylvaTreePostprocessor : AssetPostprocessor
{
    static readonly Regex Collider = new Regex(@"_collider_\d+$");
    static readonly Regex Level = new Regex(@"_LOD(\d+)$");
    const string WindShader = "Sylva/Wind";

    // The export's wind, as the glb's material extras and the FBX's user properties name it.
    [Serializable]
    class Wind
    {
        public float sylva_wind_strength = -1;
        public float sylva_wind_direction_x = 1;
        public float sylva_wind_direction_z = 0;
        public float sylva_wind_gust_frequency = 0.15f;
        public float sylva_wind_flutter = 0.1f;

        public bool Given { get { return sylva_wind_strength >= 0; } }

        public void ApplyTo(Material material)
        {
            material.SetFloat("_WindStrength", sylva_wind_strength);
            material.SetVector("_WindDirection",
                               new Vector4(sylva_wind_direction_x, sylva_wind_direction_z, 0, 0));
            material.SetFloat("_WindGustFrequency", sylva_wind_gust_frequency);
            material.SetFloat("_WindFlutter", sylva_wind_flutter);
        }
    }

    [Serializable]
    class GltfMaterial
    {
        public string name;
        public Wind extras;
    }

    [Serializable]
    class GltfDocument
    {
        public GltfMaterial[] materials;
    }

    // FBX: the mesh nodes' user properties carry the wind; their renderers have the wind
    // materials by now (OnAssignMaterialModel).
    void OnPostprocessGameObjectWithUserProperties(GameObject go, string[] names, object[] values)
    {
        var wind = new Wind();
        for (int i = 0; i < names.Length; ++i)
        {
            if (!(values[i] is IConvertible)) continue;
            float v = Convert.ToSingle(values[i]);
            switch (names[i])
            {
                case "sylva_wind_strength": wind.sylva_wind_strength = v; break;
                case "sylva_wind_direction_x": wind.sylva_wind_direction_x = v; break;
                case "sylva_wind_direction_z": wind.sylva_wind_direction_z = v; break;
                case "sylva_wind_gust_frequency": wind.sylva_wind_gust_frequency = v; break;
                case "sylva_wind_flutter": wind.sylva_wind_flutter = v; break;
            }
        }
        Renderer renderer = go.GetComponent<Renderer>();
        if (!wind.Given || renderer == null) return;
        foreach (Material m in renderer.sharedMaterials)
            if (m != null && m.shader != null && m.shader.name == WindShader)
            {
                wind.ApplyTo(m);
                EditorUtility.SetDirty(m);
            }
    }

    // The glb's (or .gltf's) material extras by material name; empty when unreadable.
    static Dictionary<string, Wind> GltfWinds(string path)
    {
        var winds = new Dictionary<string, Wind>();
        try
        {
            byte[] bytes = File.ReadAllBytes(path);
            string json = Encoding.UTF8.GetString(bytes);
            if (bytes.Length >= 20 && BitConverter.ToUInt32(bytes, 0) == 0x46546C67)  // "glTF"
                json = Encoding.UTF8.GetString(bytes, 20, (int)BitConverter.ToUInt32(bytes, 12));
            GltfDocument doc = JsonUtility.FromJson<GltfDocument>(json);
            if (doc != null && doc.materials != null)
                foreach (GltfMaterial m in doc.materials)
                    if (m.name != null && m.extras != null && m.extras.Given) winds[m.name] = m.extras;
        }
        catch (Exception) {}
        return winds;
    }

    // FBX and OBJ: colliders now; materials through OnAssignMaterialModel.
    void OnPostprocessModel(GameObject root)
    {
        AddColliders(root);
    }

    Material OnAssignMaterialModel(Material material, Renderer renderer)
    {
        Shader shader = Shader.Find(WindShader);
        if (shader == null || material == null) return null;
        string path = Folder(assetPath) + "/" + material.name + "_wind.mat";
        Material wind = AssetDatabase.LoadAssetAtPath<Material>(path);
        if (wind == null)
        {
            wind = new Material(shader) { name = material.name + "_wind" };
            wind.SetColor("_Color", material.color);
            AssetDatabase.CreateAsset(wind, path);
        }
        return wind;
    }

    static void OnPostprocessAllAssets(string[] imported, string[] deleted, string[] moved,
                                       string[] movedFrom)
    {
        foreach (string path in imported)
        {
            string ext = Path.GetExtension(path).ToLowerInvariant();
            if (ext != ".glb" && ext != ".gltf") continue;
            string asset = path;
            EditorApplication.delayCall += () => MakePrefab(asset);
        }
    }

    static void MakePrefab(string path)
    {
        GameObject model = AssetDatabase.LoadAssetAtPath<GameObject>(path);
        if (model == null) return;
        GameObject tree = Object.Instantiate(model);
        tree.name = model.name;
        AddLodGroups(tree.transform);
        AddColliders(tree);
        string folder = Folder(path);
        Dictionary<string, Wind> winds = GltfWinds(path);
        foreach (Renderer r in tree.GetComponentsInChildren<Renderer>(true))
        {
            Material[] materials = r.sharedMaterials;
            for (int i = 0; i < materials.Length; ++i)
                materials[i] = WindMaterial(folder, materials[i], winds);
            r.sharedMaterials = materials;
        }
        string prefab = folder + "/" + Path.GetFileNameWithoutExtension(path) + "_sylva.prefab";
        PrefabUtility.SaveAsPrefabAsset(tree, prefab);
        Object.DestroyImmediate(tree);
    }

    // The asset's folder with forward slashes, as the AssetDatabase wants paths.
    static string Folder(string assetPath)
    {
        return Path.GetDirectoryName(assetPath).Replace('\\', '/');
    }

    static Material WindMaterial(string folder, Material material, Dictionary<string, Wind> winds)
    {
        Shader shader = Shader.Find(WindShader);
        if (shader == null || material == null) return material;
        string path = folder + "/" + material.name + "_wind.mat";
        Material wind = AssetDatabase.LoadAssetAtPath<Material>(path);
        if (wind == null)
        {
            wind = new Material(shader) { name = material.name + "_wind" };
            Color color = material.HasProperty("baseColorFactor") ? material.GetColor("baseColorFactor")
                        : material.HasProperty("_BaseColor") ? material.GetColor("_BaseColor")
                        : material.color;
            wind.SetColor("_Color", color);
            AssetDatabase.CreateAsset(wind, path);
        }
        Wind values;
        if (winds.TryGetValue(material.name, out values))
        {
            values.ApplyTo(wind);
            EditorUtility.SetDirty(wind);
        }
        return wind;
    }

    // A LODGroup on every node whose children are `<name>_LOD<i>` for two or more i.
    static void AddLodGroups(Transform node)
    {
        var levels = new SortedDictionary<int, Transform>();
        foreach (Transform child in node)
        {
            Match m = Level.Match(child.name);
            if (m.Success) levels[int.Parse(m.Groups[1].Value)] = child;
        }
        if (levels.Count >= 2 && node.GetComponent<LODGroup>() == null)
        {
            var lods = new List<LOD>();
            int i = 0;
            foreach (Transform level in levels.Values)
            {
                float height = i == levels.Count - 1 ? 0.01f : 0.5f / (1 << i);
                lods.Add(new LOD(height, level.GetComponentsInChildren<Renderer>(true)));
                ++i;
            }
            LODGroup group = node.gameObject.AddComponent<LODGroup>();
            group.SetLODs(lods.ToArray());
            group.RecalculateBounds();
            return;
        }
        foreach (Transform child in node) AddLodGroups(child);
    }

    // `<name>_collider_<i>` meshes become convex MeshColliders without a renderer.
    static void AddColliders(GameObject root)
    {
        foreach (MeshFilter filter in root.GetComponentsInChildren<MeshFilter>(true))
        {
            if (!Collider.IsMatch(filter.gameObject.name)) continue;
            MeshCollider collider = filter.gameObject.AddComponent<MeshCollider>();
            collider.sharedMesh = filter.sharedMesh;
            collider.convex = true;
            Renderer renderer = filter.GetComponent<Renderer>();
            if (renderer != null) Object.DestroyImmediate(renderer, true);
        }
    }
}
