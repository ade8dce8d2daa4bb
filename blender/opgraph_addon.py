# opgraph add-on for Blender 3.4+: Object > Recover design sequence.
# Install: Edit > Preferences > Add-ons > Install..., pick this file, enable "opgraph", and set
# the path to fit_sequence in the add-on's preferences.
bl_info = {
    "name": "opgraph",
    "description": "Recover the design sequence of a mesh: a live, editable modifier stack",
    "author": "opgraph",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "Object > Recover design sequence",
    "category": "Object",
}

import os
import re
import shutil
import subprocess
import tempfile
import threading

import bpy
from bpy.props import IntProperty, StringProperty


class OpgraphPreferences(bpy.types.AddonPreferences):
    bl_idname = __name__

    fit_sequence: StringProperty(name="fit_sequence", subtype='FILE_PATH', default="fit_sequence",
                                 description="The opgraph fit_sequence program (a path, or a name on PATH)")
    work_budget: IntProperty(name="Work budget", default=500000, min=100,
                             description="The search's budget in work units (500,000: about a minute on 2 cores)")


def safe_name(text):
    kept = ''.join(c if c.isalnum() or c in ' _-.' else '_' for c in text[:48])
    return kept if kept.strip(' ._-') else 'opgraph'


def export_world_mesh(obj, path):
    """The evaluated mesh of `obj` in world coordinates, as an OBJ in Blender's own axes."""
    dg = bpy.context.evaluated_depsgraph_get()
    evaluated = obj.evaluated_get(dg)
    me = evaluated.to_mesh()
    lines = ['v %.9g %.9g %.9g' % tuple(obj.matrix_world @ v.co) for v in me.vertices]
    lines += ['f ' + ' '.join(str(i + 1) for i in p.vertices) for p in me.polygons]
    evaluated.to_mesh_clear()
    with open(path, 'w') as f:
        f.write('\n'.join(lines) + '\n')


class OBJECT_OT_opgraph_recover(bpy.types.Operator):
    """Recover the design sequence of the active mesh and build it beside the source"""
    bl_idname = "object.opgraph_recover"
    bl_label = "Recover design sequence"
    bl_options = {'REGISTER', 'UNDO'}

    work_budget: IntProperty(name="Work budget", default=0, min=0,
                             description="0: the add-on preferences' budget")

    @classmethod
    def poll(cls, context):
        return context.active_object is not None and context.active_object.type == 'MESH'

    def start(self, context):
        prefs = context.preferences.addons[__name__].preferences
        source = context.active_object
        self.folder = tempfile.mkdtemp(prefix='opgraph_')
        mesh_path = os.path.join(self.folder, safe_name(source.name) + '.obj')
        export_world_mesh(source, mesh_path)
        self.out = os.path.join(self.folder, 'out')
        budget = self.work_budget or prefs.work_budget
        # Raw axes: the mesh was written in Blender's world frame, so the result lands on the source.
        command = [bpy.path.abspath(prefs.fit_sequence), '--input', mesh_path, '--out', self.out,
                   '--blender-axes', 'raw', '--work-budget', str(budget)]
        self.fraction = 0.0
        self.errors = []
        self.process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.reader = threading.Thread(target=self.read_progress, daemon=True)
        self.reader.start()

    def read_progress(self):
        for line in self.process.stdout:
            found = re.search(r'\[progress\] .*?(\d+)%', line)
            if found:
                self.fraction = int(found.group(1)) / 100.0
        self.errors = self.process.stderr.read().strip().splitlines()

    def finish(self, context):
        self.reader.join()
        try:
            if self.process.returncode != 0:
                message = self.errors[-1] if self.errors else 'exit code %d' % self.process.returncode
                self.report({'ERROR'}, 'opgraph: ' + message)
                return {'CANCELLED'}
            script = os.path.join(self.out, 'rebuild_blender.py')
            with open(script) as f:
                code = compile(f.read(), script, 'exec')
            exec(code, {'__name__': 'opgraph_rebuild', 'OPGRAPH_ARGV': []})
            self.report({'INFO'}, 'opgraph: built %s' % context.view_layer.objects.active.name)
            return {'FINISHED'}
        finally:
            shutil.rmtree(self.folder, ignore_errors=True)

    def execute(self, context):
        self.start(context)
        if bpy.app.background:  # no event loop: wait
            self.process.wait()
            return self.finish(context)
        context.window_manager.progress_begin(0, 100)
        self.timer = context.window_manager.event_timer_add(0.5, window=context.window)
        context.window_manager.modal_handler_add(self)
        return {'RUNNING_MODAL'}

    def modal(self, context, event):
        if event.type == 'ESC':
            self.process.terminate()
        if event.type != 'TIMER':
            return {'PASS_THROUGH'}
        context.window_manager.progress_update(int(100 * self.fraction))
        context.workspace.status_text_set('opgraph: recovering the design sequence, %d%% (Esc cancels)'
                                          % int(100 * self.fraction))
        if self.process.poll() is None:
            return {'RUNNING_MODAL'}
        context.window_manager.event_timer_remove(self.timer)
        context.window_manager.progress_end()
        context.workspace.status_text_set(None)
        return self.finish(context)


def menu_entry(self, context):
    self.layout.operator(OBJECT_OT_opgraph_recover.bl_idname)


def register():
    bpy.utils.register_class(OpgraphPreferences)
    bpy.utils.register_class(OBJECT_OT_opgraph_recover)
    bpy.types.VIEW3D_MT_object.append(menu_entry)


def unregister():
    bpy.types.VIEW3D_MT_object.remove(menu_entry)
    bpy.utils.unregister_class(OBJECT_OT_opgraph_recover)
    bpy.utils.unregister_class(OpgraphPreferences)
