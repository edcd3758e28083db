//! Every X3D node animed reads, and the common ones beside them, with each
//! field's access (initializeOnly, inputOutput, inputOnly, outputOnly) and
//! type: what ROUTE and IS checks (`events.rs`) and the unknown-field check
//! look X3D fields up in, as `node_table` does for VRML97.
//!
//! Written from the node definitions of X3D 4.0 (ISO/IEC 19775-1:2023),
//! as the Web3D Consortium publishes them machine-readably in the X3D
//! Unified Object Model (X3dUnifiedObjectModel-4.0.xml): the components
//! Core, Grouping, Rendering, Shape, Geometry3D, Geometry2D, Text,
//! Lighting, Texturing, CubeMapTexturing, Interpolation, Followers, Time,
//! EventUtilities, Navigation, Networking, EnvironmentalEffects, the
//! sensors (EnvironmentalSensor, PointingDeviceSensor, KeyDeviceSensor),
//! Scripting, Shaders, Layering and H-Anim (ISO/IEC 19774), plus
//! CADGeometry's IndexedQuadSet/QuadSet and Sound's AudioClip, Sound and
//! SpatialSound. Version 4.0 is a superset of 3.x for these nodes (fields
//! added, some initializeOnly fields made inputOutput), so a 3.x file is
//! checked against the wider 4.0 interface: a 3.x file using a 4.0-only
//! field is not flagged.
//!
//! Every X3D node also has `metadata` (inputOutput SFNode, the Core
//! component's X3DNode), added by [`builtin`]. One string per node keeps the table
//! short: `access:type:name` words, access `f` initializeOnly, `x`
//! inputOutput, `i` inputOnly, `o` outputOnly. Script and the shader nodes
//! list only their own fields; what they declare comes from the file.

use super::node_table::{Access, Entry};

/// The nodes, by name, with their fields (see the module doc).
const NODES: &[(&str, &str)] = &[
    (
        "AcousticProperties",
        "x:SFFloat:absorption x:SFString:description x:SFFloat:diffuse \
         x:SFBool:enabled x:SFFloat:refraction x:SFFloat:specular",
    ),
    (
        "Anchor",
        "i:MFNode:addChildren x:SFTime:autoRefresh \
         x:SFTime:autoRefreshTimeLimit f:SFVec3f:bboxCenter \
         x:SFBool:bboxDisplay f:SFVec3f:bboxSize x:MFNode:children \
         x:SFString:description x:SFBool:load x:MFString:parameter \
         i:MFNode:removeChildren x:MFString:url x:SFBool:visible",
    ),
    (
        "Appearance",
        "x:SFNode:acousticProperties x:SFFloat:alphaCutoff x:SFString:alphaMode \
         x:SFNode:backMaterial x:SFNode:fillProperties x:SFNode:lineProperties \
         x:SFNode:material x:SFNode:pointProperties x:MFNode:shaders \
         x:SFNode:texture x:SFNode:textureTransform",
    ),
    (
        "Arc2D",
        "f:SFFloat:endAngle f:SFFloat:radius f:SFFloat:startAngle",
    ),
    (
        "ArcClose2D",
        "f:SFString:closureType f:SFFloat:endAngle f:SFFloat:radius \
         f:SFBool:solid f:SFFloat:startAngle",
    ),
    (
        "AudioClip",
        "x:SFTime:autoRefresh x:SFTime:autoRefreshTimeLimit \
         x:SFString:description o:SFTime:duration_changed o:SFTime:elapsedTime \
         x:SFBool:enabled x:SFFloat:gain o:SFBool:isActive o:SFBool:isPaused \
         x:SFBool:load x:SFBool:loop x:SFTime:pauseTime x:SFFloat:pitch \
         x:SFTime:resumeTime x:SFTime:startTime x:SFTime:stopTime \
         x:MFString:url",
    ),
    (
        "Background",
        "x:MFString:backUrl o:SFTime:bindTime x:MFString:bottomUrl \
         x:MFString:frontUrl x:MFFloat:groundAngle x:MFColor:groundColor \
         o:SFBool:isBound x:MFString:leftUrl x:MFString:rightUrl \
         i:SFBool:set_bind x:MFFloat:skyAngle x:MFColor:skyColor \
         x:MFString:topUrl x:SFFloat:transparency",
    ),
    (
        "Billboard",
        "i:MFNode:addChildren x:SFVec3f:axisOfRotation f:SFVec3f:bboxCenter \
         x:SFBool:bboxDisplay f:SFVec3f:bboxSize x:MFNode:children \
         i:MFNode:removeChildren x:SFBool:visible",
    ),
    (
        "BooleanFilter",
        "o:SFBool:inputFalse o:SFBool:inputNegate o:SFBool:inputTrue \
         i:SFBool:set_boolean",
    ),
    (
        "BooleanSequencer",
        "x:MFFloat:key x:MFBool:keyValue i:SFBool:next i:SFBool:previous \
         i:SFFloat:set_fraction o:SFBool:value_changed",
    ),
    ("BooleanToggle", "i:SFBool:set_boolean x:SFBool:toggle"),
    (
        "BooleanTrigger",
        "i:SFTime:set_triggerTime o:SFBool:triggerTrue",
    ),
    ("Box", "f:SFVec3f:size f:SFBool:solid"),
    ("Circle2D", "f:SFFloat:radius"),
    ("ClipPlane", "x:SFBool:enabled x:SFVec4f:plane"),
    (
        "Collision",
        "i:MFNode:addChildren f:SFVec3f:bboxCenter x:SFBool:bboxDisplay \
         f:SFVec3f:bboxSize x:MFNode:children o:SFTime:collideTime \
         x:SFString:description x:SFBool:enabled o:SFBool:isActive \
         f:SFNode:proxy i:MFNode:removeChildren x:SFBool:visible",
    ),
    ("Color", "x:MFColor:color"),
    (
        "ColorChaser",
        "f:SFTime:duration f:SFColor:initialDestination f:SFColor:initialValue \
         o:SFBool:isActive i:SFColor:set_destination i:SFColor:set_value \
         o:SFColor:value_changed",
    ),
    (
        "ColorDamper",
        "f:SFColor:initialDestination f:SFColor:initialValue o:SFBool:isActive \
         f:SFInt32:order i:SFColor:set_destination i:SFColor:set_value \
         x:SFTime:tau x:SFFloat:tolerance o:SFColor:value_changed",
    ),
    (
        "ColorInterpolator",
        "x:MFFloat:key x:MFColor:keyValue i:SFFloat:set_fraction \
         o:SFColor:value_changed",
    ),
    ("ColorRGBA", "x:MFColorRGBA:color"),
    (
        "ComposedCubeMapTexture",
        "x:SFNode:backTexture x:SFNode:bottomTexture x:SFString:description \
         x:SFNode:frontTexture x:SFNode:leftTexture x:SFNode:rightTexture \
         f:SFNode:textureProperties x:SFNode:topTexture",
    ),
    (
        "ComposedShader",
        "i:SFBool:activate o:SFBool:isSelected o:SFBool:isValid \
         f:SFString:language x:MFNode:parts",
    ),
    (
        "Cone",
        "x:SFBool:bottom f:SFFloat:bottomRadius f:SFFloat:height x:SFBool:side \
         f:SFBool:solid",
    ),
    ("Coordinate", "x:MFVec3f:point"),
    (
        "CoordinateChaser",
        "f:SFTime:duration f:MFVec3f:initialDestination f:MFVec3f:initialValue \
         o:SFBool:isActive i:MFVec3f:set_destination i:MFVec3f:set_value \
         o:MFVec3f:value_changed",
    ),
    (
        "CoordinateDamper",
        "f:MFVec3f:initialDestination f:MFVec3f:initialValue o:SFBool:isActive \
         f:SFInt32:order i:MFVec3f:set_destination i:MFVec3f:set_value \
         x:SFTime:tau x:SFFloat:tolerance o:MFVec3f:value_changed",
    ),
    ("CoordinateDouble", "x:MFVec3d:point"),
    (
        "CoordinateInterpolator",
        "x:MFFloat:key x:MFVec3f:keyValue i:SFFloat:set_fraction \
         o:MFVec3f:value_changed",
    ),
    (
        "CoordinateInterpolator2D",
        "x:MFFloat:key x:MFVec2f:keyValue i:SFFloat:set_fraction \
         o:MFVec2f:value_changed",
    ),
    (
        "Cylinder",
        "x:SFBool:bottom f:SFFloat:height f:SFFloat:radius x:SFBool:side \
         f:SFBool:solid x:SFBool:top",
    ),
    (
        "CylinderSensor",
        "x:SFBool:autoOffset x:SFRotation:axisRotation x:SFString:description \
         x:SFFloat:diskAngle x:SFBool:enabled o:SFBool:isActive o:SFBool:isOver \
         x:SFFloat:maxAngle x:SFFloat:minAngle x:SFFloat:offset \
         o:SFRotation:rotation_changed o:SFVec3f:trackPoint_changed",
    ),
    (
        "DirectionalLight",
        "x:SFFloat:ambientIntensity x:SFColor:color x:SFVec3f:direction \
         x:SFBool:global x:SFFloat:intensity x:SFBool:on \
         x:SFFloat:shadowIntensity x:SFBool:shadows",
    ),
    (
        "Disk2D",
        "f:SFFloat:innerRadius f:SFFloat:outerRadius f:SFBool:solid",
    ),
    (
        "EaseInEaseOut",
        "x:MFVec2f:easeInEaseOut x:MFFloat:key \
         o:SFFloat:modifiedFraction_changed i:SFFloat:set_fraction",
    ),
    (
        "ElevationGrid",
        "x:MFNode:attrib f:SFBool:ccw x:SFNode:color f:SFBool:colorPerVertex \
         f:SFFloat:creaseAngle x:SFNode:fogCoord f:MFFloat:height \
         x:SFNode:normal f:SFBool:normalPerVertex i:MFFloat:set_height \
         f:SFBool:solid x:SFNode:texCoord f:SFInt32:xDimension \
         f:SFFloat:xSpacing f:SFInt32:zDimension f:SFFloat:zSpacing",
    ),
    (
        "Extrusion",
        "f:SFBool:beginCap f:SFBool:ccw f:SFBool:convex f:SFFloat:creaseAngle \
         f:MFVec2f:crossSection f:SFBool:endCap f:MFRotation:orientation \
         f:MFVec2f:scale i:MFVec2f:set_crossSection \
         i:MFRotation:set_orientation i:MFVec2f:set_scale i:MFVec3f:set_spine \
         f:SFBool:solid f:MFVec3f:spine",
    ),
    (
        "FillProperties",
        "x:SFBool:filled x:SFColor:hatchColor x:SFBool:hatched \
         x:SFInt32:hatchStyle",
    ),
    (
        "FloatVertexAttribute",
        "f:SFString:name f:SFInt32:numComponents x:MFFloat:value",
    ),
    (
        "Fog",
        "o:SFTime:bindTime x:SFColor:color x:SFString:fogType o:SFBool:isBound \
         i:SFBool:set_bind x:SFFloat:visibilityRange",
    ),
    ("FogCoordinate", "x:MFFloat:depth"),
    (
        "FontStyle",
        "x:MFString:family x:SFBool:horizontal x:MFString:justify \
         x:SFString:language x:SFBool:leftToRight x:SFFloat:size \
         x:SFFloat:spacing x:SFBool:topToBottom",
    ),
    (
        "GeneratedCubeMapTexture",
        "x:SFString:description f:SFInt32:size f:SFNode:textureProperties \
         x:SFString:update",
    ),
    (
        "Group",
        "i:MFNode:addChildren f:SFVec3f:bboxCenter x:SFBool:bboxDisplay \
         f:SFVec3f:bboxSize x:MFNode:children i:MFNode:removeChildren \
         x:SFBool:visible",
    ),
    (
        "HAnimDisplacer",
        "x:MFInt32:coordIndex x:SFString:description x:MFVec3f:displacements \
         x:SFString:name x:SFFloat:weight",
    ),
    (
        "HAnimHumanoid",
        "f:SFVec3f:bboxCenter x:SFBool:bboxDisplay f:SFVec3f:bboxSize \
         x:SFVec3f:center x:SFString:description x:MFString:info \
         x:MFVec3f:jointBindingPositions x:MFRotation:jointBindingRotations \
         x:MFVec3f:jointBindingScales x:MFNode:joints x:SFInt32:loa \
         x:MFNode:motions x:MFBool:motionsEnabled x:SFString:name \
         x:SFRotation:rotation x:SFVec3f:scale x:SFRotation:scaleOrientation \
         x:MFNode:segments x:MFNode:sites x:SFString:skeletalConfiguration \
         x:MFNode:skeleton x:MFNode:skin x:SFNode:skinBindingCoords \
         x:SFNode:skinBindingNormals x:SFNode:skinCoord x:SFNode:skinNormal \
         x:SFVec3f:translation x:SFString:version x:MFNode:viewpoints \
         x:SFBool:visible",
    ),
    (
        "HAnimJoint",
        "i:MFNode:addChildren f:SFVec3f:bboxCenter x:SFBool:bboxDisplay \
         f:SFVec3f:bboxSize x:SFVec3f:center x:MFNode:children \
         x:SFString:description x:MFNode:displacers \
         x:SFRotation:limitOrientation x:MFFloat:llimit x:SFString:name \
         i:MFNode:removeChildren x:SFRotation:rotation x:SFVec3f:scale \
         x:SFRotation:scaleOrientation x:MFInt32:skinCoordIndex \
         x:MFFloat:skinCoordWeight x:MFFloat:stiffness x:SFVec3f:translation \
         x:MFFloat:ulimit x:SFBool:visible",
    ),
    (
        "HAnimMotion",
        "x:SFString:channels x:MFBool:channelsEnabled o:SFTime:cycleTime \
         x:SFString:description o:SFTime:elapsedTime x:SFBool:enabled \
         x:SFInt32:endFrame o:SFInt32:frameCount x:SFTime:frameDuration \
         x:SFInt32:frameIncrement x:SFInt32:frameIndex x:SFString:joints \
         x:SFInt32:loa x:SFBool:loop x:SFString:name i:SFBool:next \
         i:SFBool:previous x:SFInt32:startFrame x:MFFloat:values",
    ),
    (
        "HAnimSegment",
        "i:MFNode:addChildren f:SFVec3f:bboxCenter x:SFBool:bboxDisplay \
         f:SFVec3f:bboxSize x:SFVec3f:centerOfMass x:MFNode:children \
         x:SFNode:coord x:SFString:description x:MFNode:displacers \
         x:SFFloat:mass x:MFFloat:momentsOfInertia x:SFString:name \
         i:MFNode:removeChildren x:SFBool:visible",
    ),
    (
        "HAnimSite",
        "i:MFNode:addChildren f:SFVec3f:bboxCenter x:SFBool:bboxDisplay \
         f:SFVec3f:bboxSize x:SFVec3f:center x:MFNode:children \
         x:SFString:description x:SFString:name i:MFNode:removeChildren \
         x:SFRotation:rotation x:SFVec3f:scale x:SFRotation:scaleOrientation \
         x:SFVec3f:translation x:SFBool:visible",
    ),
    (
        "ImageCubeMapTexture",
        "x:SFTime:autoRefresh x:SFTime:autoRefreshTimeLimit \
         x:SFString:description x:SFBool:load f:SFNode:textureProperties \
         x:MFString:url",
    ),
    (
        "ImageTexture",
        "x:SFTime:autoRefresh x:SFTime:autoRefreshTimeLimit \
         x:SFString:description x:SFBool:load f:SFBool:repeatS f:SFBool:repeatT \
         f:SFNode:textureProperties x:MFString:url",
    ),
    (
        "IndexedFaceSet",
        "x:MFNode:attrib f:SFBool:ccw x:SFNode:color f:MFInt32:colorIndex \
         f:SFBool:colorPerVertex f:SFBool:convex x:SFNode:coord \
         f:MFInt32:coordIndex f:SFFloat:creaseAngle x:SFNode:fogCoord \
         x:SFNode:normal f:MFInt32:normalIndex f:SFBool:normalPerVertex \
         i:MFInt32:set_colorIndex i:MFInt32:set_coordIndex \
         i:MFInt32:set_normalIndex i:MFInt32:set_texCoordIndex f:SFBool:solid \
         x:SFNode:texCoord f:MFInt32:texCoordIndex",
    ),
    (
        "IndexedLineSet",
        "x:MFNode:attrib x:SFNode:color f:MFInt32:colorIndex \
         f:SFBool:colorPerVertex x:SFNode:coord f:MFInt32:coordIndex \
         x:SFNode:fogCoord x:SFNode:normal i:MFInt32:set_colorIndex \
         i:MFInt32:set_coordIndex",
    ),
    (
        "IndexedQuadSet",
        "x:MFNode:attrib f:SFBool:ccw x:SFNode:color f:SFBool:colorPerVertex \
         x:SFNode:coord x:SFNode:fogCoord f:MFInt32:index x:SFNode:normal \
         f:SFBool:normalPerVertex i:MFInt32:set_index f:SFBool:solid \
         x:SFNode:texCoord",
    ),
    (
        "IndexedTriangleFanSet",
        "x:MFNode:attrib f:SFBool:ccw x:SFNode:color f:SFBool:colorPerVertex \
         x:SFNode:coord x:SFNode:fogCoord f:MFInt32:index x:SFNode:normal \
         f:SFBool:normalPerVertex i:MFInt32:set_index f:SFBool:solid \
         x:SFNode:texCoord",
    ),
    (
        "IndexedTriangleSet",
        "x:MFNode:attrib f:SFBool:ccw x:SFNode:color f:SFBool:colorPerVertex \
         x:SFNode:coord x:SFNode:fogCoord f:MFInt32:index x:SFNode:normal \
         f:SFBool:normalPerVertex i:MFInt32:set_index f:SFBool:solid \
         x:SFNode:texCoord",
    ),
    (
        "IndexedTriangleStripSet",
        "x:MFNode:attrib f:SFBool:ccw x:SFNode:color f:SFBool:colorPerVertex \
         x:SFNode:coord x:SFNode:fogCoord f:MFInt32:index x:SFNode:normal \
         f:SFBool:normalPerVertex i:MFInt32:set_index f:SFBool:solid \
         x:SFNode:texCoord",
    ),
    (
        "Inline",
        "x:SFTime:autoRefresh x:SFTime:autoRefreshTimeLimit \
         f:SFVec3f:bboxCenter x:SFBool:bboxDisplay f:SFVec3f:bboxSize \
         x:SFString:description x:SFBool:global x:SFBool:load x:MFString:url \
         x:SFBool:visible",
    ),
    (
        "IntegerSequencer",
        "x:MFFloat:key x:MFInt32:keyValue i:SFBool:next i:SFBool:previous \
         i:SFFloat:set_fraction o:SFInt32:value_changed",
    ),
    (
        "IntegerTrigger",
        "x:SFInt32:integerKey i:SFBool:set_boolean o:SFInt32:triggerValue",
    ),
    (
        "KeySensor",
        "o:SFInt32:actionKeyPress o:SFInt32:actionKeyRelease o:SFBool:altKey \
         o:SFBool:controlKey x:SFString:description x:SFBool:enabled \
         o:SFBool:isActive o:SFString:keyPress o:SFString:keyRelease \
         o:SFBool:shiftKey",
    ),
    (
        "LOD",
        "i:MFNode:addChildren f:SFVec3f:bboxCenter x:SFBool:bboxDisplay \
         f:SFVec3f:bboxSize f:SFVec3f:center x:MFNode:children \
         f:SFBool:forceTransitions o:SFInt32:level_changed f:MFFloat:range \
         i:MFNode:removeChildren x:SFBool:visible",
    ),
    (
        "Layer",
        "i:MFNode:addChildren x:MFNode:children x:MFString:objectType \
         x:SFBool:pickable i:MFNode:removeChildren x:SFNode:viewport \
         x:SFBool:visible",
    ),
    (
        "LayerSet",
        "x:SFInt32:activeLayer x:MFNode:layers x:MFInt32:order",
    ),
    (
        "LineProperties",
        "x:SFBool:applied x:SFInt32:linetype x:SFFloat:linewidthScaleFactor",
    ),
    (
        "LineSet",
        "x:MFNode:attrib x:SFNode:color x:SFNode:coord x:SFNode:fogCoord \
         x:SFNode:normal x:MFInt32:vertexCount",
    ),
    (
        "LoadSensor",
        "x:MFNode:children x:SFString:description x:SFBool:enabled \
         o:SFBool:isActive o:SFBool:isLoaded o:SFTime:loadTime \
         o:SFFloat:progress x:SFTime:timeOut",
    ),
    (
        "LocalFog",
        "x:SFColor:color x:SFBool:enabled x:SFString:fogType \
         x:SFFloat:visibilityRange",
    ),
    (
        "Material",
        "x:SFFloat:ambientIntensity x:SFNode:ambientTexture \
         x:SFString:ambientTextureMapping x:SFColor:diffuseColor \
         x:SFNode:diffuseTexture x:SFString:diffuseTextureMapping \
         x:SFColor:emissiveColor x:SFNode:emissiveTexture \
         x:SFString:emissiveTextureMapping x:SFFloat:normalScale \
         x:SFNode:normalTexture x:SFString:normalTextureMapping \
         x:SFFloat:occlusionStrength x:SFNode:occlusionTexture \
         x:SFString:occlusionTextureMapping x:SFFloat:shininess \
         x:SFNode:shininessTexture x:SFString:shininessTextureMapping \
         x:SFColor:specularColor x:SFNode:specularTexture \
         x:SFString:specularTextureMapping x:SFFloat:transparency",
    ),
    (
        "Matrix3VertexAttribute",
        "f:SFString:name x:MFMatrix3f:value",
    ),
    (
        "Matrix4VertexAttribute",
        "f:SFString:name x:MFMatrix4f:value",
    ),
    (
        "MetadataBoolean",
        "x:SFString:name x:SFString:reference x:MFBool:value",
    ),
    (
        "MetadataDouble",
        "x:SFString:name x:SFString:reference x:MFDouble:value",
    ),
    (
        "MetadataFloat",
        "x:SFString:name x:SFString:reference x:MFFloat:value",
    ),
    (
        "MetadataInteger",
        "x:SFString:name x:SFString:reference x:MFInt32:value",
    ),
    (
        "MetadataSet",
        "x:SFString:name x:SFString:reference x:MFNode:value",
    ),
    (
        "MetadataString",
        "x:SFString:name x:SFString:reference x:MFString:value",
    ),
    (
        "MovieTexture",
        "x:SFTime:autoRefresh x:SFTime:autoRefreshTimeLimit \
         x:SFString:description o:SFTime:duration_changed o:SFTime:elapsedTime \
         x:SFBool:enabled x:SFFloat:gain o:SFBool:isActive o:SFBool:isPaused \
         x:SFBool:load x:SFBool:loop x:SFTime:pauseTime x:SFFloat:pitch \
         f:SFBool:repeatS f:SFBool:repeatT x:SFTime:resumeTime x:SFFloat:speed \
         x:SFTime:startTime x:SFTime:stopTime f:SFNode:textureProperties \
         x:MFString:url",
    ),
    (
        "MultiTexture",
        "x:SFFloat:alpha x:SFColor:color x:SFString:description \
         x:MFString:function x:MFString:mode x:MFString:source x:MFNode:texture",
    ),
    ("MultiTextureCoordinate", "x:MFNode:texCoord"),
    ("MultiTextureTransform", "x:MFNode:textureTransform"),
    (
        "NavigationInfo",
        "x:MFFloat:avatarSize o:SFTime:bindTime x:SFBool:headlight \
         o:SFBool:isBound i:SFBool:set_bind x:SFFloat:speed \
         o:SFBool:transitionComplete x:SFTime:transitionTime \
         x:MFString:transitionType x:MFString:type x:SFFloat:visibilityLimit",
    ),
    ("Normal", "x:MFVec3f:vector"),
    (
        "NormalInterpolator",
        "x:MFFloat:key x:MFVec3f:keyValue i:SFFloat:set_fraction \
         o:MFVec3f:value_changed",
    ),
    (
        "OrientationChaser",
        "f:SFTime:duration f:SFRotation:initialDestination \
         f:SFRotation:initialValue o:SFBool:isActive \
         i:SFRotation:set_destination i:SFRotation:set_value \
         o:SFRotation:value_changed",
    ),
    (
        "OrientationDamper",
        "f:SFRotation:initialDestination f:SFRotation:initialValue \
         o:SFBool:isActive f:SFInt32:order i:SFRotation:set_destination \
         i:SFRotation:set_value x:SFTime:tau x:SFFloat:tolerance \
         o:SFRotation:value_changed",
    ),
    (
        "OrientationInterpolator",
        "x:MFFloat:key x:MFRotation:keyValue i:SFFloat:set_fraction \
         o:SFRotation:value_changed",
    ),
    (
        "OrthoViewpoint",
        "o:SFTime:bindTime x:SFVec3f:centerOfRotation x:SFString:description \
         x:SFFloat:farDistance x:MFFloat:fieldOfView o:SFBool:isBound \
         x:SFBool:jump x:SFNode:navigationInfo x:SFFloat:nearDistance \
         x:SFRotation:orientation x:SFVec3f:position x:SFBool:retainUserOffsets \
         i:SFBool:set_bind x:SFBool:viewAll",
    ),
    (
        "PackagedShader",
        "i:SFBool:activate x:SFTime:autoRefresh x:SFTime:autoRefreshTimeLimit \
         x:SFString:description o:SFBool:isSelected o:SFBool:isValid \
         f:SFString:language x:SFBool:load x:MFString:url",
    ),
    (
        "PhysicalMaterial",
        "x:SFColor:baseColor x:SFNode:baseTexture x:SFString:baseTextureMapping \
         x:SFColor:emissiveColor x:SFNode:emissiveTexture \
         x:SFString:emissiveTextureMapping x:SFFloat:metallic \
         x:SFNode:metallicRoughnessTexture \
         x:SFString:metallicRoughnessTextureMapping x:SFFloat:normalScale \
         x:SFNode:normalTexture x:SFString:normalTextureMapping \
         x:SFFloat:occlusionStrength x:SFNode:occlusionTexture \
         x:SFString:occlusionTextureMapping x:SFFloat:roughness \
         x:SFFloat:transparency",
    ),
    (
        "PixelTexture",
        "x:SFString:description x:SFImage:image f:SFBool:repeatS \
         f:SFBool:repeatT f:SFNode:textureProperties",
    ),
    (
        "PlaneSensor",
        "x:SFBool:autoOffset x:SFRotation:axisRotation x:SFString:description \
         x:SFBool:enabled o:SFBool:isActive o:SFBool:isOver \
         x:SFVec2f:maxPosition x:SFVec2f:minPosition x:SFVec3f:offset \
         o:SFVec3f:trackPoint_changed o:SFVec3f:translation_changed",
    ),
    (
        "PointLight",
        "x:SFFloat:ambientIntensity x:SFVec3f:attenuation x:SFColor:color \
         x:SFBool:global x:SFFloat:intensity x:SFVec3f:location x:SFBool:on \
         x:SFFloat:radius x:SFFloat:shadowIntensity x:SFBool:shadows",
    ),
    (
        "PointProperties",
        "x:SFVec3f:attenuation x:SFFloat:pointSizeMaxValue \
         x:SFFloat:pointSizeMinValue x:SFFloat:pointSizeScaleFactor",
    ),
    (
        "PointSet",
        "x:MFNode:attrib x:SFNode:color x:SFNode:coord x:SFNode:fogCoord \
         x:SFNode:normal",
    ),
    ("Polyline2D", "f:MFVec2f:lineSegments"),
    ("Polypoint2D", "x:MFVec2f:point"),
    (
        "PositionChaser",
        "f:SFTime:duration f:SFVec3f:initialDestination f:SFVec3f:initialValue \
         o:SFBool:isActive i:SFVec3f:set_destination i:SFVec3f:set_value \
         o:SFVec3f:value_changed",
    ),
    (
        "PositionChaser2D",
        "f:SFTime:duration f:SFVec2f:initialDestination f:SFVec2f:initialValue \
         o:SFBool:isActive i:SFVec2f:set_destination i:SFVec2f:set_value \
         o:SFVec2f:value_changed",
    ),
    (
        "PositionDamper",
        "f:SFVec3f:initialDestination f:SFVec3f:initialValue o:SFBool:isActive \
         f:SFInt32:order i:SFVec3f:set_destination i:SFVec3f:set_value \
         x:SFTime:tau x:SFFloat:tolerance o:SFVec3f:value_changed",
    ),
    (
        "PositionDamper2D",
        "f:SFVec2f:initialDestination f:SFVec2f:initialValue o:SFBool:isActive \
         f:SFInt32:order i:SFVec2f:set_destination i:SFVec2f:set_value \
         x:SFTime:tau x:SFFloat:tolerance o:SFVec2f:value_changed",
    ),
    (
        "PositionInterpolator",
        "x:MFFloat:key x:MFVec3f:keyValue i:SFFloat:set_fraction \
         o:SFVec3f:value_changed",
    ),
    (
        "PositionInterpolator2D",
        "x:MFFloat:key x:MFVec2f:keyValue i:SFFloat:set_fraction \
         o:SFVec2f:value_changed",
    ),
    (
        "ProgramShader",
        "i:SFBool:activate o:SFBool:isSelected o:SFBool:isValid \
         f:SFString:language x:MFNode:programs",
    ),
    (
        "ProximitySensor",
        "x:SFVec3f:center o:SFVec3f:centerOfRotation_changed \
         x:SFString:description x:SFBool:enabled o:SFTime:enterTime \
         o:SFTime:exitTime o:SFBool:isActive o:SFRotation:orientation_changed \
         o:SFVec3f:position_changed x:SFVec3f:size",
    ),
    (
        "QuadSet",
        "x:MFNode:attrib f:SFBool:ccw x:SFNode:color f:SFBool:colorPerVertex \
         x:SFNode:coord x:SFNode:fogCoord x:SFNode:normal \
         f:SFBool:normalPerVertex f:SFBool:solid x:SFNode:texCoord",
    ),
    ("Rectangle2D", "f:SFVec2f:size f:SFBool:solid"),
    (
        "ScalarChaser",
        "f:SFTime:duration f:SFFloat:initialDestination f:SFFloat:initialValue \
         o:SFBool:isActive i:SFFloat:set_destination i:SFFloat:set_value \
         o:SFFloat:value_changed",
    ),
    (
        "ScalarDamper",
        "f:SFFloat:initialDestination f:SFFloat:initialValue o:SFBool:isActive \
         f:SFInt32:order i:SFFloat:set_destination i:SFFloat:set_value \
         x:SFTime:tau x:SFFloat:tolerance o:SFFloat:value_changed",
    ),
    (
        "ScalarInterpolator",
        "x:MFFloat:key x:MFFloat:keyValue i:SFFloat:set_fraction \
         o:SFFloat:value_changed",
    ),
    (
        "Script",
        "x:SFTime:autoRefresh x:SFTime:autoRefreshTimeLimit \
         x:SFString:description f:SFBool:directOutput x:SFBool:load \
         f:SFBool:mustEvaluate x:SFString:sourceCode x:MFString:url",
    ),
    (
        "ShaderPart",
        "x:SFTime:autoRefresh x:SFTime:autoRefreshTimeLimit \
         x:SFString:description x:SFBool:load x:SFString:sourceCode \
         f:SFString:type x:MFString:url",
    ),
    (
        "ShaderProgram",
        "x:SFTime:autoRefresh x:SFTime:autoRefreshTimeLimit \
         x:SFString:description x:SFBool:load x:SFString:sourceCode \
         f:SFString:type x:MFString:url",
    ),
    (
        "Shape",
        "x:SFNode:appearance f:SFVec3f:bboxCenter x:SFBool:bboxDisplay \
         f:SFVec3f:bboxSize x:SFBool:castShadow x:SFNode:geometry \
         x:SFBool:visible",
    ),
    (
        "Sound",
        "x:SFString:description x:SFVec3f:direction x:SFBool:enabled \
         x:SFFloat:intensity x:SFVec3f:location x:SFFloat:maxBack \
         x:SFFloat:maxFront x:SFFloat:minBack x:SFFloat:minFront \
         x:SFFloat:priority x:SFNode:source f:SFBool:spatialize",
    ),
    (
        "SpatialSound",
        "x:MFNode:children x:SFFloat:coneInnerAngle x:SFFloat:coneOuterAngle \
         x:SFFloat:coneOuterGain x:SFString:description x:SFVec3f:direction \
         x:SFString:distanceModel x:SFBool:dopplerEnabled x:SFBool:enabled \
         x:SFBool:enableHRTF x:SFFloat:gain x:SFFloat:intensity \
         x:SFVec3f:location x:SFFloat:maxDistance x:SFFloat:priority \
         x:SFFloat:referenceDistance x:SFFloat:rolloffFactor \
         f:SFBool:spatialize",
    ),
    ("Sphere", "f:SFFloat:radius f:SFBool:solid"),
    (
        "SphereSensor",
        "x:SFBool:autoOffset x:SFString:description x:SFBool:enabled \
         o:SFBool:isActive o:SFBool:isOver x:SFRotation:offset \
         o:SFRotation:rotation_changed o:SFVec3f:trackPoint_changed",
    ),
    (
        "SplinePositionInterpolator",
        "x:SFBool:closed x:MFFloat:key x:MFVec3f:keyValue x:MFVec3f:keyVelocity \
         x:SFBool:normalizeVelocity i:SFFloat:set_fraction \
         o:SFVec3f:value_changed",
    ),
    (
        "SplinePositionInterpolator2D",
        "x:SFBool:closed x:MFFloat:key x:MFVec2f:keyValue x:MFVec2f:keyVelocity \
         x:SFBool:normalizeVelocity i:SFFloat:set_fraction \
         o:SFVec2f:value_changed",
    ),
    (
        "SplineScalarInterpolator",
        "x:SFBool:closed x:MFFloat:key x:MFFloat:keyValue x:MFFloat:keyVelocity \
         x:SFBool:normalizeVelocity i:SFFloat:set_fraction \
         o:SFFloat:value_changed",
    ),
    (
        "SpotLight",
        "x:SFFloat:ambientIntensity x:SFVec3f:attenuation x:SFFloat:beamWidth \
         x:SFColor:color x:SFFloat:cutOffAngle x:SFVec3f:direction \
         x:SFBool:global x:SFFloat:intensity x:SFVec3f:location x:SFBool:on \
         x:SFFloat:radius x:SFFloat:shadowIntensity x:SFBool:shadows",
    ),
    (
        "SquadOrientationInterpolator",
        "x:MFFloat:key x:MFRotation:keyValue x:SFBool:normalizeVelocity \
         i:SFFloat:set_fraction o:SFRotation:value_changed",
    ),
    (
        "StaticGroup",
        "f:SFVec3f:bboxCenter x:SFBool:bboxDisplay f:SFVec3f:bboxSize \
         f:MFNode:children x:SFBool:visible",
    ),
    (
        "StringSensor",
        "x:SFBool:deletionAllowed x:SFString:description x:SFBool:enabled \
         o:SFString:enteredText o:SFString:finalText o:SFBool:isActive",
    ),
    (
        "Switch",
        "i:MFNode:addChildren f:SFVec3f:bboxCenter x:SFBool:bboxDisplay \
         f:SFVec3f:bboxSize x:MFNode:children i:MFNode:removeChildren \
         x:SFBool:visible x:SFInt32:whichChoice",
    ),
    (
        "TexCoordChaser2D",
        "f:SFTime:duration f:MFVec2f:initialDestination f:MFVec2f:initialValue \
         o:SFBool:isActive i:MFVec2f:set_destination i:MFVec2f:set_value \
         o:MFVec2f:value_changed",
    ),
    (
        "TexCoordDamper2D",
        "f:MFVec2f:initialDestination f:MFVec2f:initialValue o:SFBool:isActive \
         f:SFInt32:order i:MFVec2f:set_destination i:MFVec2f:set_value \
         x:SFTime:tau x:SFFloat:tolerance o:MFVec2f:value_changed",
    ),
    (
        "Text",
        "x:SFNode:fontStyle x:MFFloat:length o:MFVec2f:lineBounds \
         x:SFFloat:maxExtent o:SFVec3f:origin f:SFBool:solid x:MFString:string \
         o:SFVec2f:textBounds",
    ),
    (
        "TextureBackground",
        "x:SFNode:backTexture o:SFTime:bindTime x:SFNode:bottomTexture \
         x:SFNode:frontTexture x:MFFloat:groundAngle x:MFColor:groundColor \
         o:SFBool:isBound x:SFNode:leftTexture x:SFNode:rightTexture \
         i:SFBool:set_bind x:MFFloat:skyAngle x:MFColor:skyColor \
         x:SFNode:topTexture x:SFFloat:transparency",
    ),
    ("TextureCoordinate", "x:SFString:mapping x:MFVec2f:point"),
    (
        "TextureCoordinateGenerator",
        "x:SFString:mapping x:SFString:mode x:MFFloat:parameter",
    ),
    (
        "TextureProperties",
        "x:SFFloat:anisotropicDegree x:SFColorRGBA:borderColor \
         x:SFInt32:borderWidth x:SFString:boundaryModeR \
         x:SFString:boundaryModeS x:SFString:boundaryModeT \
         f:SFBool:generateMipMaps x:SFString:magnificationFilter \
         x:SFString:minificationFilter x:SFString:textureCompression \
         x:SFFloat:texturePriority",
    ),
    (
        "TextureTransform",
        "x:SFVec2f:center x:SFString:mapping x:SFFloat:rotation x:SFVec2f:scale \
         x:SFVec2f:translation",
    ),
    (
        "TimeSensor",
        "x:SFTime:cycleInterval o:SFTime:cycleTime x:SFString:description \
         o:SFTime:elapsedTime x:SFBool:enabled o:SFFloat:fraction_changed \
         o:SFBool:isActive o:SFBool:isPaused x:SFBool:loop x:SFTime:pauseTime \
         x:SFTime:resumeTime x:SFTime:startTime x:SFTime:stopTime o:SFTime:time",
    ),
    ("TimeTrigger", "i:SFBool:set_boolean o:SFTime:triggerTime"),
    (
        "TouchSensor",
        "x:SFString:description x:SFBool:enabled o:SFVec3f:hitNormal_changed \
         o:SFVec3f:hitPoint_changed o:SFVec2f:hitTexCoord_changed \
         o:SFBool:isActive o:SFBool:isOver o:SFTime:touchTime",
    ),
    (
        "Transform",
        "i:MFNode:addChildren f:SFVec3f:bboxCenter x:SFBool:bboxDisplay \
         f:SFVec3f:bboxSize x:SFVec3f:center x:MFNode:children \
         i:MFNode:removeChildren x:SFRotation:rotation x:SFVec3f:scale \
         x:SFRotation:scaleOrientation x:SFVec3f:translation x:SFBool:visible",
    ),
    (
        "TransformSensor",
        "x:SFVec3f:center x:SFString:description x:SFBool:enabled \
         o:SFTime:enterTime o:SFTime:exitTime o:SFBool:isActive \
         o:SFRotation:orientation_changed o:SFVec3f:position_changed \
         x:SFVec3f:size x:SFNode:targetObject",
    ),
    (
        "TriangleFanSet",
        "x:MFNode:attrib f:SFBool:ccw x:SFNode:color f:SFBool:colorPerVertex \
         x:SFNode:coord x:MFInt32:fanCount x:SFNode:fogCoord x:SFNode:normal \
         f:SFBool:normalPerVertex f:SFBool:solid x:SFNode:texCoord",
    ),
    (
        "TriangleSet",
        "x:MFNode:attrib f:SFBool:ccw x:SFNode:color f:SFBool:colorPerVertex \
         x:SFNode:coord x:SFNode:fogCoord x:SFNode:normal \
         f:SFBool:normalPerVertex f:SFBool:solid x:SFNode:texCoord",
    ),
    ("TriangleSet2D", "f:SFBool:solid x:MFVec2f:vertices"),
    (
        "TriangleStripSet",
        "x:MFNode:attrib f:SFBool:ccw x:SFNode:color f:SFBool:colorPerVertex \
         x:SFNode:coord x:SFNode:fogCoord x:SFNode:normal \
         f:SFBool:normalPerVertex f:SFBool:solid x:MFInt32:stripCount \
         x:SFNode:texCoord",
    ),
    (
        "TwoSidedMaterial",
        "x:SFFloat:ambientIntensity x:SFFloat:backAmbientIntensity \
         x:SFColor:backDiffuseColor x:SFColor:backEmissiveColor \
         x:SFFloat:backShininess x:SFColor:backSpecularColor \
         x:SFFloat:backTransparency x:SFColor:diffuseColor \
         x:SFColor:emissiveColor x:SFBool:separateBackColor x:SFFloat:shininess \
         x:SFColor:specularColor x:SFFloat:transparency",
    ),
    (
        "UnlitMaterial",
        "x:SFColor:emissiveColor x:SFNode:emissiveTexture \
         x:SFString:emissiveTextureMapping x:SFFloat:normalScale \
         x:SFNode:normalTexture x:SFString:normalTextureMapping \
         x:SFFloat:transparency",
    ),
    (
        "Viewpoint",
        "o:SFTime:bindTime x:SFVec3f:centerOfRotation x:SFString:description \
         x:SFFloat:farDistance x:SFFloat:fieldOfView o:SFBool:isBound \
         x:SFBool:jump x:SFNode:navigationInfo x:SFFloat:nearDistance \
         x:SFRotation:orientation x:SFVec3f:position x:SFBool:retainUserOffsets \
         i:SFBool:set_bind x:SFBool:viewAll",
    ),
    (
        "ViewpointGroup",
        "x:SFVec3f:center x:MFNode:children x:SFString:description \
         x:SFBool:displayed x:SFBool:retainUserOffsets x:SFVec3f:size",
    ),
    (
        "Viewport",
        "i:MFNode:addChildren f:SFVec3f:bboxCenter x:SFBool:bboxDisplay \
         f:SFVec3f:bboxSize x:MFNode:children x:MFFloat:clipBoundary \
         i:MFNode:removeChildren x:SFBool:visible",
    ),
    (
        "VisibilitySensor",
        "x:SFVec3f:center x:SFString:description x:SFBool:enabled \
         o:SFTime:enterTime o:SFTime:exitTime o:SFBool:isActive x:SFVec3f:size",
    ),
    ("WorldInfo", "x:MFString:info x:SFString:title"),
];

/// The interface of built-in X3D node `kind` (its `metadata` included),
/// or `None` for any other name (PROTOs, vendor extensions, components
/// not in the table).
pub fn builtin(kind: &str) -> Option<Vec<Entry>> {
    let (_, fields) = NODES.iter().find(|(k, _)| *k == kind)?;
    let mut out = vec![(Access::Exposed, "SFNode", "metadata")];
    out.extend(fields.split_whitespace().filter_map(entry));
    Some(out)
}

/// Whether nodes of type `kind` declare fields of their own in the file
/// (Script, and X3D's shader nodes): those names are the file's, not the
/// table's.
pub fn declares_fields(kind: &str) -> bool {
    matches!(
        kind,
        "Script" | "ComposedShader" | "PackagedShader" | "ShaderProgram"
    )
}

/// One `access:type:name` word.
fn entry(word: &'static str) -> Option<Entry> {
    let mut it = word.splitn(3, ':');
    let access = match it.next()? {
        "f" => Access::Field,
        "x" => Access::Exposed,
        "i" => Access::In,
        "o" => Access::Out,
        _ => return None,
    };
    Some((access, it.next()?, it.next()?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_word_is_well_formed_and_names_are_unique() {
        assert_eq!(NODES.len(), 151);
        for (kind, fields) in NODES {
            let words: Vec<&str> = fields.split_whitespace().collect();
            let entries = builtin(kind).unwrap();
            assert_eq!(entries.len(), words.len() + 1, "{kind}: a bad word");
            for (i, e) in entries.iter().enumerate() {
                assert!(!entries[..i].iter().any(|d| d.2 == e.2), "{kind}.{}", e.2);
                assert!(
                    e.1.starts_with("SF") || e.1.starts_with("MF"),
                    "{kind}.{}",
                    e.2
                );
            }
        }
        assert!(NODES.windows(2).all(|w| w[0].0 < w[1].0), "sorted");
    }

    #[test]
    fn fields_are_as_the_x3d_spec_defines_them() {
        use Access::*;
        let has = |kind: &str, e: Entry| builtin(kind).unwrap().contains(&e);
        // Read off the node definitions of the Time, Interpolation,
        // Grouping, Rendering, Shape and Navigation components.
        assert!(has("TimeSensor", (Out, "SFFloat", "fraction_changed")));
        assert!(has("TimeSensor", (Exposed, "SFTime", "pauseTime")));
        assert!(has("PositionInterpolator", (In, "SFFloat", "set_fraction")));
        assert!(has("Transform", (Exposed, "SFVec3f", "translation")));
        assert!(has("Transform", (Field, "SFVec3f", "bboxSize")));
        assert!(has("ColorRGBA", (Exposed, "MFColorRGBA", "color")));
        assert!(has("PhysicalMaterial", (Exposed, "SFColor", "baseColor")));
        assert!(has("Switch", (Exposed, "MFNode", "children")));
        assert!(has("Viewpoint", (Exposed, "SFString", "description")));
        assert!(has("Box", (Exposed, "SFNode", "metadata")));
        assert!(builtin("Switch").unwrap().iter().all(|e| e.2 != "choice"));
        assert!(builtin("KambiNavigationInfo").is_none());
    }
}
